"""Check my code: a student's own ray-tracing pieces inside RayLab (issue 35).

检查我的代码：学生自己写的光线追踪函数在 RayLab 中运行，逐条光线与精确结果对照。

Every piece a ray-tracing course asks students to write has a function here with the
course's signature and its contract in English and Chinese (``help(raylab.student.
intersect_sphere)``). Give yours to :func:`use`; then

* :func:`trace` traces one pixel sample with your intersection functions *in place of* the
  engine's (the tree is your tree) and, beside it, with the engine's own; every call of
  your code is judged against the exact (CGAL) oracle: ``agrees``, ``off_by_ulps``,
  ``wrong_hit``, ``missed_hit``, ``spurious_hit``, ``non_finite`` or ``exception``
  (a recorded tree judged ray by ray, as the web export's bug-hunt steps are, can also say
  ``wrong_weight``: right geometry, wrong weight);
* :func:`render` renders an image with your intersection functions;
* :func:`judge` runs one optics or sampling piece (reflect, refract, Fresnel, Schlick,
  Lambert, Phong, Blinn-Phong, cosine-weighted hemisphere sampling, the spawn offset) on
  fixed cases against the engine's reference rule (a chi-squared test for the sampler).

Vectors reach your code as NumPy arrays of three floats; a t is a float, or None for a
miss. 向量以含三个浮点数的 NumPy 数组传入；t 为浮点数，未命中时返回 None。
"""

import inspect as _inspect

from . import _raylab

# The pieces: name -> (parameters, what it returns, contract in English, in Chinese).
PIECES = {
    "intersect_sphere": (
        ("origin", "direction", "center", "radius", "t_min", "t_max"), "float | None",
        "Ray-sphere intersection: the nearest t in [t_min, t_max] with |origin + t direction"
        " - center| = radius (direction is unit length), or None. From inside the sphere"
        " that is the exit point.",
        "光线与球求交：返回 [t_min, t_max] 内满足 |origin + t·direction − center| = radius 的最小"
        " t（direction 为单位向量），未命中返回 None。光线起点在球内时，交点是出射点。"),
    "intersect_plane": (
        ("origin", "direction", "point", "normal", "t_min", "t_max"), "float | None",
        "Ray-plane intersection: t with dot(origin + t direction - point, normal) = 0 in"
        " [t_min, t_max], or None (a ray parallel to the plane misses it).",
        "光线与平面求交：返回 [t_min, t_max] 内满足 (origin + t·direction − point)·normal = 0"
        " 的 t，否则返回 None（与平面平行的光线视为未命中）。"),
    "intersect_box": (
        ("origin", "direction", "box_min", "box_max", "t_min", "t_max"), "float | None",
        "Ray-box intersection by slabs: the nearest t in [t_min, t_max] on the boundary of"
        " the axis-aligned box [box_min, box_max], or None. (A rotated box is given in its"
        " own frame, where it is [-1, 1]^3; direction is then not unit length.)",
        "用平板法（slab）求光线与轴对齐包围盒 [box_min, box_max] 的交点：返回边界上"
        " [t_min, t_max] 内的最小 t，否则返回 None。（旋转的盒子在其自身坐标系中给出，"
        "即 [-1, 1]^3，此时 direction 不是单位向量。）"),
    "intersect_triangle": (
        ("origin", "direction", "v0", "v1", "v2", "t_min", "t_max"), "float | None",
        "Ray-triangle intersection (e.g. Moller-Trumbore): t in [t_min, t_max] where the ray"
        " meets the triangle (v0, v1, v2), both sides, edges included, or None.",
        "光线与三角形求交（例如 Möller–Trumbore 算法）：返回光线与三角形 (v0, v1, v2) 交点的"
        " t（双面，含边），须在 [t_min, t_max] 内，否则返回 None。"),
    "reflect": (
        ("d", "n"), "vector",
        "Mirror reflection of the incident direction d about the unit normal n:"
        " d - 2 dot(d, n) n.",
        "入射方向 d 关于单位法线 n 的镜面反射方向：d − 2(d·n)n。"),
    "refract": (
        ("d", "n", "eta"), "vector | None",
        "Refraction of the unit incident direction d through a surface whose unit normal n"
        " faces against d, eta = eta_i / eta_t (Snell's law); None on total internal"
        " reflection.",
        "单位入射方向 d 经过表面折射后的方向（斯涅尔定律），单位法线 n 与 d 方向相反，"
        "eta = η_i / η_t；发生全反射时返回 None。"),
    "fresnel": (
        ("cos_i", "eta"), "float",
        "Exact (unpolarised) Fresnel reflectance of a dielectric for the incidence cosine"
        " cos_i and eta = eta_i / eta_t; 1 on total internal reflection.",
        "电介质的精确（非偏振）菲涅耳反射率，入射角余弦为 cos_i，eta = η_i / η_t；"
        "全反射时为 1。"),
    "schlick": (
        ("cos_i", "eta"), "float",
        "Schlick's approximation R0 + (1 - R0)(1 - cos)^5 with R0 = ((eta - 1)/(eta + 1))^2,"
        " the cosine taken on the less dense side; 1 on total internal reflection.",
        "Schlick 近似 R0 + (1 − R0)(1 − cosθ)^5，R0 = ((eta − 1)/(eta + 1))^2，余弦取光疏介质"
        "一侧的角；全反射时为 1。"),
    "lambert": (
        ("n", "l"), "float",
        "Lambert's cosine factor max(0, dot(n, l)) for unit normal n and unit direction l"
        " towards the light.",
        "朗伯余弦项 max(0, n·l)，n 为单位法线，l 为指向光源的单位方向。"),
    "phong": (
        ("n", "v", "l", "shininess"), "float",
        "Phong's highlight (R . V)^shininess with R = 2 (N . L) N - L the mirror direction of"
        " the light; 0 when R . V <= 0 or N . L <= 0. v points to the viewer, l to the light.",
        "Phong 高光 (R·V)^shininess，R = 2(N·L)N − L 为光线的镜面反射方向；R·V ≤ 0 或"
        " N·L ≤ 0 时为 0。v 指向观察者，l 指向光源。"),
    "blinn_phong": (
        ("n", "v", "l", "shininess"), "float",
        "Blinn-Phong highlight (N . H)^shininess with the half vector H = (L + V) / |L + V|;"
        " 0 when N . L <= 0.",
        "Blinn-Phong 高光 (N·H)^shininess，半程向量 H = (L + V) / |L + V|；N·L ≤ 0 时为 0。"),
    "sample_cosine_hemisphere": (
        ("u1", "u2"), "(vector, float)",
        "A direction of the hemisphere z > 0 with density cos(theta) / pi, from two uniform"
        " numbers in [0, 1), and that density (the pdf, per steradian).",
        "由 [0, 1) 内的两个均匀随机数生成 z > 0 半球上按余弦加权的方向（概率密度"
        " cosθ/π），并返回该方向的概率密度 pdf（每球面度）。"),
    "spawn_offset": (
        ("p", "n", "d"), "vector",
        "The origin of a secondary ray leaving the hit point p (unit normal n) in direction d:"
        " p moved off the surface to the side d goes to, so the new ray does not hit the"
        " surface it leaves (no shadow acne).",
        "次级光线的起点：把交点 p（单位法线 n）沿法线移向 d 所在的一侧，使新光线不会再次击中"
        "它离开的表面（避免阴影痤疮）。"),
}

GEOMETRY = ("intersect_sphere", "intersect_plane", "intersect_box", "intersect_triangle")

_active = {}


class StudentCodeError(TypeError):
    """A student's function cannot be used: wrong name, not callable, wrong signature.

    The message names the file and line of the function and what was expected, in English
    and Chinese.
    """


def _where(fn):
    try:
        return "%s, line %d" % (_inspect.getsourcefile(fn), fn.__code__.co_firstlineno)
    except (TypeError, AttributeError):
        return repr(fn)


def _check_signature(name, fn):
    params, returns, _, _ = PIECES[name]
    expected = "%s(%s) -> %s" % (name, ", ".join(params), returns)
    if not callable(fn):
        raise StudentCodeError(
            "%s must be a function %s, not %r\n%s 必须是函数 %s，而不是 %r"
            % (name, expected, fn, name, expected, fn))
    try:
        signature = _inspect.signature(fn)
        signature.bind(*params)
    except ValueError:
        return  # a builtin without a signature: judged when called
    except TypeError:
        raise StudentCodeError(
            "%s: %s takes (%s) but the engine calls %s\n%s：%s 的参数是 (%s)，而引擎按 %s 调用"
            % (_where(fn), getattr(fn, "__name__", name), ", ".join(signature.parameters),
               expected, _where(fn), getattr(fn, "__name__", name),
               ", ".join(signature.parameters), expected)) from None


def use(**functions):
    """Makes the engine call your functions in place of its own (geometry) and judges them.

    ``use(intersect_sphere=my_sphere)``; ``use()`` with nothing goes back to the engine's
    own pieces. Names are those of :data:`PIECES`; a wrong name or signature raises
    :class:`StudentCodeError` naming the file and line.

    让引擎用你的函数代替它自己的（几何求交部分）并逐条评判；不带参数调用 ``use()``
    则恢复引擎自己的实现。
    """
    for name, fn in functions.items():
        if name not in PIECES:
            raise StudentCodeError(
                "unknown piece %r: the pieces are %s\n未知的函数名 %r，可用的有 %s"
                % (name, ", ".join(PIECES), name, ", ".join(PIECES)))
        _check_signature(name, fn)
    _active.clear()
    _active.update(functions)


def active():
    """The functions given to :func:`use` (a copy)."""
    return dict(_active)


def _pixel(pixel):
    x, y = pixel
    return int(x), int(y)


def trace(scene, pixel=(0, 0), sample=0, *, algorithm=None, spp=None, seed=None,
          max_depth=None, ray=None):
    """Traces one pixel sample with your functions and with the engine's, and judges them.

    Returns a ``raylab.StudentTrace``: ``student`` and ``reference`` (two ``raylab.Trace``),
    ``verdicts`` (one per ray of your tree), ``calls`` (every call of your code with the
    ray, your t, the exact t and the verdict), ``first_divergent`` (the first ray whose
    verdict fails, or -1) and ``passes``.

    用你的函数和引擎自己的函数分别追踪同一像素样本，并逐条光线评判。
    """
    x, y = _pixel(pixel)
    geometry = {k: v for k, v in _active.items() if k in GEOMETRY}
    return _raylab.student_trace(scene, geometry, x, y, sample, algorithm, spp, seed,
                                 max_depth, ray)


def render(scene, *, algorithm=None, spp=1, seed=None, max_depth=None, threads=0):
    """Renders the scene with your intersection functions (H x W x 3 float32, linear RGB).

    A call that raises counts as a miss here; :func:`trace` shows which rays raised.
    用你的求交函数渲染整幅图像；抛出异常的调用在此按未命中处理，用 trace 查看具体光线。
    """
    geometry = {k: v for k, v in _active.items() if k in GEOMETRY}
    return _raylab.student_render(scene, geometry, algorithm, spp, seed, max_depth, threads)


def _stub(name):
    params, returns, en, zh = PIECES[name]

    def piece(*args):
        raise NotImplementedError(
            "%s is yours to write: %s\n%s 需要你来实现：%s" % (name, en, name, zh))

    piece.__name__ = name
    piece.__qualname__ = name
    piece.__doc__ = "%s(%s) -> %s\n\n%s\n\n%s" % (name, ", ".join(params), returns, en, zh)
    piece.__signature__ = _inspect.Signature(
        [_inspect.Parameter(p, _inspect.Parameter.POSITIONAL_OR_KEYWORD) for p in params])
    return piece


for _name in PIECES:
    globals()[_name] = _stub(_name)



def save_view(path, scene, trace, width=400, height=300, language="en"):
    """Writes a PNG: your tree coloured by verdict (with its legend) beside the engine's
    tree coloured by ray kind. Needs an X server (xvfb-run), like raylab.save_view.

    保存一张 PNG：左边是按评判结果着色的你的光线树，右边是按光线类型着色的引擎光线树。
    """
    _raylab.student_save_view(path, scene, trace, width, height, language)


from ._judge import judge  # noqa: E402,F401
