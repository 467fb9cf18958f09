"""raylab.student.judge: one piece of a student's code on fixed, documented cases.

Geometry answers are judged against the exact (CGAL) oracle, the optics against the
engine's reference rule, the sampler by a chi-squared test against its density.
"""

import math
import random

import numpy as np

from . import _raylab

# Relative tolerance of optics answers (vectors by component, scalars): far above the
# rounding of a careful double computation, far below any mistake of the cases.
TOLERANCE = 1e-9


def _unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def _deg(a):
    return math.radians(a)


def _geometry_cases(piece):
    """(case name, shape, ray, how the student is called) for one intersection piece."""
    Ray = _raylab.Ray
    out = []
    if piece == "intersect_sphere":
        def add(name, centre, radius, o, d, t_min=0.0, t_max=math.inf):
            ray = Ray(o, d, t_min, t_max)
            out.append((name, _raylab.Sphere(centre, radius), ray,
                        (ray.origin, ray.direction, centre, radius, ray.t_min, ray.t_max)))
        add("front hit", (0, 0, 0), 1, (0, 0, 5), (0, 0, -1))
        add("off-centre hit", (0, 0, 0), 1, (0.3, 0.4, 5), (0, 0, -1))
        add("from inside", (0, 0, 0), 1, (0, 0, 0.2), (0, 0.6, -0.8))
        add("behind the origin", (0, 0, 0), 1, (0, 0, 5), (0, 0, 1))
        add("miss", (0, 0, 0), 1, (2, 0, 5), (0, 0, -1))
        add("tangent", (0, 0, 0), 1, (1, 0, 5), (0, 0, -1))
        add("beyond t_max", (0, 0, 0), 1, (0, 0, 5), (0, 0, -1), 0.0, 3.0)
        add("huge scale", (1e6, 2e6, -3e6), 5e5, (1e6, 2e6, 0), (0, 0, -1))
        add("tiny scale", (1e-6, 0, 0), 1e-7, (1e-6, 0, 1e-5), (0, 0, -1))
    elif piece == "intersect_plane":
        def add(name, point, normal, o, d, t_min=0.0, t_max=math.inf):
            ray = Ray(o, d, t_min, t_max)
            n = tuple(_unit(normal))
            out.append((name, _raylab.Plane(point, n), ray,
                        (ray.origin, ray.direction, np.array(point, float), np.array(n),
                         ray.t_min, ray.t_max)))
        add("front hit", (0, 0, 0), (0, 1, 0), (0, 2, 0), (0, -1, 0))
        add("slanted hit", (0, 1, 0), (0, 1, 1), (3, 4, 5), (-0.2, -1, -0.4))
        add("from behind", (0, 0, 0), (0, 1, 0), (0, -2, 0), (0.3, 1, 0))
        add("behind the origin", (0, 0, 0), (0, 1, 0), (0, 2, 0), (0, 1, 0))
        add("parallel", (0, 0, 0), (0, 1, 0), (0, 2, 0), (1, 0, 0))
        add("huge scale", (0, -1e7, 0), (0, 1, 0), (3e6, 1e7, 0), (0, -1, 0))
        add("tiny scale", (0, 1e-9, 0), (0, 1, 0), (0, 3e-9, 0), (0.1, -1, 0))
    elif piece == "intersect_box":
        def add(name, centre, size, o, d, t_min=0.0, t_max=math.inf):
            ray = Ray(o, d, t_min, t_max)
            c, s = np.array(centre, float), np.array(size, float)
            out.append((name, _raylab.Box(centre, size), ray,
                        (ray.origin, ray.direction, c - s / 2, c + s / 2, ray.t_min,
                         ray.t_max)))
        add("front hit", (0, 0, 0), (2, 2, 2), (0, 0, 5), (0, 0, -1))
        add("slanted hit", (0, 0, 0), (2, 1, 3), (4, 3, 5), (-0.7, -0.5, -0.9))
        add("from inside", (0, 0, 0), (2, 2, 2), (0.2, 0.1, 0), (1, 0.3, 0))
        add("behind the origin", (0, 0, 0), (2, 2, 2), (0, 0, 5), (0, 0, 1))
        add("miss", (0, 0, 0), (2, 2, 2), (3, 0, 5), (0, 0, -1))
        add("parallel to a slab", (0, 0, 0), (2, 2, 2), (0.5, 0.5, 5), (0, 0, -1))
        add("parallel outside a slab", (0, 0, 0), (2, 2, 2), (1.5, 0.5, 5), (0, 0, -1))
        add("huge scale", (1e6, 0, 0), (4e5, 4e5, 4e5), (1e6, 0, 1e6), (0.01, 0, -1))
        add("tiny scale", (0, 0, 0), (1e-7, 1e-7, 1e-7), (0, 0, 1e-6), (0.01, 0, -1))
    elif piece == "intersect_triangle":
        def add(name, v0, v1, v2, o, d, t_min=0.0, t_max=math.inf):
            ray = Ray(o, d, t_min, t_max)
            vs = [np.array(v, float) for v in (v0, v1, v2)]
            out.append((name, _raylab.Triangle(v0, v1, v2), ray,
                        (ray.origin, ray.direction, *vs, ray.t_min, ray.t_max)))
        tri = ((-1, 0, 0), (1, 0, 0), (0, 2, 0))
        add("front hit", *tri, (0, 0.5, 3), (0, 0, -1))
        add("back side", *tri, (0.2, 0.5, -3), (0, 0, 1))
        add("slanted hit", *tri, (2, 3, 4), (-0.45, -0.6, -1))
        add("miss beside", *tri, (2, 0.5, 3), (0, 0, -1))
        add("behind the origin", *tri, (0, 0.5, 3), (0, 0, 1))
        add("parallel", *tri, (0, 0.5, 3), (1, 0, 0))
        add("huge scale", (-1e6, 0, -1e6), (1e6, 0, -1e6), (0, 2e6, -1e6), (0, 5e5, 1e6),
            (0, 0, -1))
        add("tiny scale", (-1e-7, 0, 0), (1e-7, 0, 0), (0, 2e-7, 0), (0, 5e-8, 1e-6),
            (0, 0, -1))
    return out


def _call(fn, args):
    """(answer, error text): the student's answer, or what went wrong with its line."""
    try:
        return fn(*[np.array(a, float) if isinstance(a, tuple) else a for a in args]), ""
    except MemoryError:
        raise  # the memory limit: the whole check stops (raylab._check_child reports it)
    except Exception as error:  # the student's code: every failure is reported
        import traceback
        frames = traceback.extract_tb(error.__traceback__)
        where = " (%s, line %d, in %s)" % (frames[-1].filename, frames[-1].lineno,
                                          frames[-1].name) if frames else ""
        return None, "%s: %s%s" % (type(error).__name__, error, where)


def _judge_geometry(piece, fn):
    results = []
    for name, shape, ray, args in _geometry_cases(piece):
        answer, error = _call(fn, args)
        if not error and answer is not None and (isinstance(answer, bool)
                                                 or not hasattr(answer, "__float__")):
            error = "returned %r: expected a float t or None (a miss)" % (answer,)
        student = None if error or answer is None else float(answer)
        verdict = _raylab.student_judge_geometry(shape, ray, student, error)
        verdict["case"] = name
        results.append(verdict)
    return results


def _close(a, b):
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape != b.shape:
        return False
    return bool(np.all(np.abs(a - b) <= TOLERANCE * np.maximum(1.0, np.abs(b))))


def _optics_cases(piece):
    """(case name, arguments, reference answer) for one optics piece."""
    out = []
    if piece == "reflect":
        for name, d, n in [("45 degrees on a floor", (1, -1, 0), (0, 1, 0)),
                           ("normal incidence", (0, 0, -1), (0, 0, 1)),
                           ("grazing", (1, -1e-3, 0), (0, 1, 0)),
                           ("slanted normal", (0.3, -0.2, -0.9), (0.2, 0.5, 0.8))]:
            d, n = tuple(_unit(d)), tuple(_unit(n))
            out.append((name, (d, n), _raylab.ref_reflect(d, n)))
    elif piece == "refract":
        for name, angle, eta in [("air to glass, normal incidence", 0, 1 / 1.5),
                                 ("air to glass, 30 degrees", 30, 1 / 1.5),
                                 ("air to glass, 75 degrees", 75, 1 / 1.5),
                                 ("glass to air, 30 degrees", 30, 1.5),
                                 ("glass to air, 45 degrees (total internal reflection)", 45,
                                  1.5)]:
            d = (math.sin(_deg(angle)), -math.cos(_deg(angle)), 0.0)
            n = (0.0, 1.0, 0.0)
            out.append((name, (d, n, eta), _raylab.ref_refract(d, n, eta)))
    elif piece in ("fresnel", "schlick"):
        ref = _raylab.ref_fresnel if piece == "fresnel" else _raylab.ref_schlick
        for name, angle, eta in [("air to glass, normal incidence", 0, 1 / 1.5),
                                 ("air to glass, 60 degrees", 60, 1 / 1.5),
                                 ("air to glass, grazing 89 degrees", 89, 1 / 1.5),
                                 ("glass to air, 30 degrees", 30, 1.5),
                                 ("glass to air, 60 degrees (total internal reflection)", 60,
                                  1.5)]:
            c = math.cos(_deg(angle))
            out.append((name, (c, eta), ref(c, eta)))
    elif piece == "lambert":
        for name, n, l in [("light overhead", (0, 1, 0), (0, 1, 0)),
                           ("light at 60 degrees", (0, 1, 0), (math.sin(_deg(60)),
                                                               math.cos(_deg(60)), 0)),
                           ("light below the horizon", (0, 1, 0), (0, -0.6, 0.8))]:
            n, l = tuple(_unit(n)), tuple(_unit(l))
            out.append((name, (n, l), max(0.0, float(np.dot(n, l)))))
    elif piece in ("phong", "blinn_phong"):
        ref = _raylab.ref_phong if piece == "phong" else _raylab.ref_blinn_phong
        for name, v, l, s in [("viewer on the mirror direction", (-1, 1, 0), (1, 1, 0), 20),
                              ("viewer off the mirror direction", (-0.5, 1, 0.3), (1, 1, 0), 20),
                              ("light below the surface", (0, 1, 0), (1, -0.2, 0), 10),
                              ("broad lobe", (0, 1, 0.4), (0.3, 1, 0), 2)]:
            n, v, l = (0.0, 1.0, 0.0), tuple(_unit(v)), tuple(_unit(l))
            out.append((name, (n, v, l, s), ref(n, v, l, s)))
    return out


def _judge_optics(piece, fn):
    results = []
    for name, args, reference in _optics_cases(piece):
        answer, error = _call(fn, args)
        result = {"case": name, "student": answer, "reference": reference, "error": error}
        if error:
            result["verdict"] = "exception"
        elif reference is None or answer is None:
            result["verdict"] = "agrees" if reference is None and answer is None else "differs"
        elif not np.all(np.isfinite(np.asarray(answer, float))):
            result["verdict"] = "non_finite"
        else:
            result["verdict"] = "agrees" if _close(answer, reference) else "differs"
        results.append(result)
    return results


def _chi2_cosine(directions):
    """Chi-squared of directions against the density cos(theta) / pi: z^2 and phi are then
    uniform; 10 x 10 equal cells. Returns (statistic, degrees of freedom)."""
    counts = np.zeros((10, 10))
    for w in directions:
        z2 = min(max(w[2] * w[2], 0.0), 1.0 - 1e-12)
        phi = (math.atan2(w[1], w[0]) + 2 * math.pi) % (2 * math.pi)
        counts[int(z2 * 10), min(int(phi / (2 * math.pi) * 10), 9)] += 1
    expected = len(directions) / 100.0
    return float(((counts - expected) ** 2 / expected).sum()), 99


# The chi-squared statistic with 99 degrees of freedom exceeds this with probability 1e-6.
CHI2_LIMIT = 185.0


def _judge_sampler(fn):
    rng = random.Random(35)
    results, directions = [], []
    bad_pdf = None
    for i in range(20000):
        u1, u2 = rng.random(), rng.random()
        answer, error = _call(fn, (u1, u2))
        if error:
            return [{"case": "sample (%g, %g)" % (u1, u2), "verdict": "exception",
                     "error": error, "student": None, "reference": None}]
        try:
            w, pdf = answer
            w = np.asarray(w, float)
            pdf = float(pdf)
        except (TypeError, ValueError):
            return [{"case": "sample (%g, %g)" % (u1, u2), "verdict": "wrong_type",
                     "error": "returned %r: expected (direction, pdf)" % (answer,),
                     "student": None, "reference": None}]
        if w.shape != (3,) or not np.all(np.isfinite(w)) or not math.isfinite(pdf):
            return [{"case": "sample (%g, %g)" % (u1, u2), "verdict": "non_finite",
                     "error": "", "student": repr(answer), "reference": None}]
        if bad_pdf is None and abs(pdf - max(w[2], 0.0) / math.pi) > 1e-6:
            bad_pdf = {"case": "pdf of sample (%g, %g)" % (u1, u2), "verdict": "differs",
                       "student": pdf, "reference": max(w[2], 0.0) / math.pi, "error": ""}
        directions.append(w)
    lengths = np.linalg.norm(np.array(directions), axis=1)
    unit = bool(np.all(np.abs(lengths - 1.0) < 1e-9))
    results.append({"case": "directions are unit length", "error": "",
                    "verdict": "agrees" if unit else "differs",
                    "student": float(lengths.max()), "reference": 1.0})
    upper = all(w[2] >= 0.0 for w in directions)
    results.append({"case": "directions in the hemisphere z >= 0", "error": "",
                    "verdict": "agrees" if upper else "differs",
                    "student": float(min(w[2] for w in directions)), "reference": 0.0})
    chi2, dof = _chi2_cosine(directions)
    results.append({"case": "chi-squared against cos(theta)/pi (20000 samples, %d dof)" % dof,
                    "error": "", "verdict": "agrees" if chi2 <= CHI2_LIMIT else "differs",
                    "student": chi2, "reference": CHI2_LIMIT})
    results.append(bad_pdf or {"case": "pdf = cos(theta)/pi", "verdict": "agrees",
                               "student": None, "reference": None, "error": ""})
    return results


def _judge_offset(fn):
    results = []
    for name, p, n, d in [("reflection off a floor", (0.3, 0.0, -2.0), (0, 1, 0), (0.6, 0.8, 0)),
                          ("refraction into the floor", (0.3, 0.0, -2.0), (0, 1, 0),
                           (0.6, -0.8, 0)),
                          ("far from the origin", (1e5, 2e5, -3e5), (0, 0, 1), (0, 0.6, 0.8)),
                          ("slanted surface", (1.0, 2.0, 3.0), tuple(_unit((1, 1, 1))),
                           tuple(_unit((1, 0.2, 0))))]:
        p, n, d = np.array(p, float), np.array(n, float), np.array(d, float)
        answer, error = _call(fn, (p, n, d))
        result = {"case": name, "student": answer, "error": error,
                  "reference": "moved at least %.3g towards the side of d" %
                               _raylab.ref_offset_distance(tuple(p))}
        if error:
            result["verdict"] = "exception"
        else:
            o = np.asarray(answer, float)
            if o.shape != (3,) or not np.all(np.isfinite(o)):
                result["verdict"] = "non_finite" if o.shape == (3,) else "wrong_type"
            else:
                along = float(np.dot(o - p, n))
                side = math.copysign(1.0, float(np.dot(d, n)))
                least = _raylab.ref_offset_distance(tuple(p))
                far = 1e-3 * max(1.0, float(np.abs(p).max()))
                ok = along * side >= least and float(np.linalg.norm(o - p)) <= far
                result["verdict"] = "agrees" if ok else "differs"
        results.append(result)
    return results


def judge(piece, fn):
    """Runs `fn` as the piece `piece` on its fixed cases; returns a dict: ``piece``,
    ``passes`` and ``cases`` (each: case, student, reference, error, verdict).

    Geometry (intersect_*) is judged against the exact oracle; reflect, refract, fresnel,
    schlick, lambert, phong and blinn_phong against the engine's reference rule (relative
    tolerance 1e-9); sample_cosine_hemisphere by unit length, hemisphere, its pdf and a
    chi-squared test of 20000 samples; spawn_offset by the side and size of the offset.

    用固定的、有文档说明的测试用例评判一个函数：几何求交与精确（CGAL）结果对照，光学函数与
    引擎的参考公式对照，采样函数用卡方检验。
    """
    from .student import PIECES, _check_signature
    if piece not in PIECES:
        raise ValueError("unknown piece %r: the pieces are %s" % (piece, ", ".join(PIECES)))
    _check_signature(piece, fn)
    if piece.startswith("intersect_"):
        cases = _judge_geometry(piece, fn)
    elif piece == "sample_cosine_hemisphere":
        cases = _judge_sampler(fn)
    elif piece == "spawn_offset":
        cases = _judge_offset(fn)
    else:
        cases = _judge_optics(piece, fn)
    passing = ("agrees", "off_by_ulps", "not_judged")
    return {"piece": piece, "passes": all(c["verdict"] in passing for c in cases),
            "cases": cases}
