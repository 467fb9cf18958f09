#!/usr/bin/env python3
"""Writes tests/web/fixture/: a small hand-made site in the format of doc/web-data.md (a
Whitted scene with four steps: a 3D step with a number question, a predict step with a choice
question, a picture step and a step that opens at depth 1), used by the browser test when
`raylab web` is not built and as the page's unit fixture. Phrases come from the phrase table.

    python3 tests/web/make_fixture.py core/src/words/phrases.json tests/web/fixture
"""
import base64
import json
import math
import shutil
import struct
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def f32(values):
    return base64.b64encode(struct.pack(f"<{len(values)}f", *values)).decode()


def u32(values):
    return base64.b64encode(struct.pack(f"<{len(values)}I", *values)).decode()


def mesh(points, polys=(), lines=(), color=(0.8, 0.8, 0.8), opacity=1.0, lit=True, width=1):
    return {"points": f32([c for p in points for c in p]), "polys": u32(polys) if polys else "",
            "lines": u32(lines) if lines else "", "verts": "", "color": list(color),
            "opacity": opacity, "lineWidth": width, "pointSize": 1, "lit": lit, "cellColors": ""}


def sphere(center, radius, n=16):
    points, polys = [], []
    for i in range(n + 1):
        theta = math.pi * i / n
        for j in range(n):
            phi = 2 * math.pi * j / n
            points.append((center[0] + radius * math.sin(theta) * math.cos(phi),
                           center[1] + radius * math.cos(theta),
                           center[2] + radius * math.sin(theta) * math.sin(phi)))
    for i in range(n):
        for j in range(n):
            a, b = i * n + j, i * n + (j + 1) % n
            polys += [4, a, b, b + n, a + n]
    return points, polys


def hit_sphere(origin, direction, center, radius):
    """Nearest t > 1e-6 of origin + t * direction on the sphere (direction unit length)."""
    oc = [o - c for o, c in zip(origin, center)]
    b = sum(d * x for d, x in zip(direction, oc))
    disc = b * b - (sum(x * x for x in oc) - radius * radius)
    roots = [t for t in (-b - math.sqrt(disc), -b + math.sqrt(disc)) if t > 1e-6]
    return min(roots)


def unit(v):
    n = math.sqrt(sum(x * x for x in v))
    return [x / n for x in v]


def refract(d, n, eta):
    cos_i = -sum(a * b for a, b in zip(d, n))
    k = 1 - eta * eta * (1 - cos_i * cos_i)
    return unit([eta * a + (eta * cos_i - math.sqrt(k)) * b for a, b in zip(d, n)])


def reflect(d, n):
    dn = sum(a * b for a, b in zip(d, n))
    return unit([a - 2 * dn * b for a, b in zip(d, n)])


COLORS = {"camera": [0.95, 0.95, 0.95], "reflection": [0.2, 0.55, 1.0], "refraction": [0.1, 0.8, 0.35],
          "shadow": [1.0, 0.75, 0.1]}


def whitted_tree():
    """A camera ray into a glass ball (centre (0,1,0), radius 1): reflection, refraction in and
    out, and shadow rays towards the light at (2, 5, 3), traced with Snell's law (n = 1.5)."""
    center, light = [0.0, 1.0, 0.0], [2.0, 5.0, 3.0]
    eye = [0.0, 1.6, 5.0]
    rays, hits = [], []

    def add(parent, kind, depth, origin, end, ends, normal=None):
        ray = {"id": len(rays), "parent": parent, "kind": kind, "depth": depth, "origin": origin,
               "end": end, "color": COLORS[kind], "width": 3 if kind == "camera" else 2,
               "ends": ends, "hit": normal is not None}
        rays.append(ray)
        if normal is not None:
            hits.append({"ray": ray["id"], "point": end, "normal": normal})
        return ray["id"]

    d0 = unit([0.1, -0.15, -1.0])
    t0 = hit_sphere(eye, d0, center, 1.0)
    p0 = [e + t0 * d for e, d in zip(eye, d0)]
    n0 = unit([p - c for p, c in zip(p0, center)])
    r0 = add(-1, "camera", 0, eye, p0, "hit", n0)
    add(r0, "shadow", 1, p0, light, "reached_light")
    add(r0, "reflection", 1, p0, [p + 4 * d for p, d in zip(p0, reflect(d0, n0))], "escaped")
    d1 = refract(d0, n0, 1 / 1.5)
    t1 = hit_sphere(p0, d1, center, 1.0)
    p1 = [p + t1 * d for p, d in zip(p0, d1)]
    n1 = unit([p - c for p, c in zip(p1, center)])
    r1 = add(r0, "refraction", 1, p0, p1, "hit", n1)
    d2 = refract(d1, [-x for x in n1], 1.5)
    t2 = -p1[1] / d2[1] if d2[1] < 0 else 4
    p2 = [p + t2 * d for p, d in zip(p1, d2)]
    r2 = add(r1, "refraction", 2, p1, p2, "hit", [0.0, 1.0, 0.0])
    add(r1, "reflection", 2, p1, [p + 1.2 * d for p, d in zip(p1, reflect(d1, [-x for x in n1]))], "max_depth")
    add(r2, "shadow", 3, p2, light, "occluded")
    return rays, hits


def view3d(phrases, hidden=False, reveal=None):
    rays, hits = whitted_tree()
    ball_points, ball_polys = sphere([0.0, 1.0, 0.0], 1.0)
    mirror_points, mirror_polys = sphere([2.2, 0.7, -1.5], 0.7)
    ground = [(-4, 0, -4), (4, 0, -4), (4, 0, 4), (-4, 0, 4)]
    frustum = [(0, 1.6, 5), (-0.4, 1.3, 4.4), (0.4, 1.3, 4.4), (0.4, 1.9, 4.4), (-0.4, 1.9, 4.4)]
    kinds = ["camera", "reflection", "refraction", "shadow"]
    return {
        "camera": {"position": [7.0, 5.0, 8.0], "focalPoint": [0.5, 1.0, 0.5], "viewUp": [0, 1, 0], "viewAngle": 30},
        "background": [0.12, 0.13, 0.16],
        "objects": [dict(mesh(ground, [4, 0, 1, 2, 3], color=(0.75, 0.72, 0.65)), name="floor"),
                    dict(mesh(ball_points, ball_polys, color=(0.7, 0.85, 0.95), opacity=0.35), name="glass ball"),
                    dict(mesh(mirror_points, mirror_polys, color=(0.8, 0.8, 0.85)), name="mirror ball")],
        "extras": [dict(mesh(frustum, lines=[2, 0, 1, 2, 0, 2, 2, 0, 3, 2, 0, 4, 5, 1, 2, 3, 4, 1],
                             color=(1, 0.3, 0.3), lit=False, width=2), kind="camera")],
        "rays": rays, "hits": hits,
        "legend": [{"kind": k, "color": COLORS[k], "label": phrases[f"ray_kind.{k}.legend"]} for k in kinds],
        "maxDepth": max(r["depth"] for r in rays), "revealDepth": reveal, "selected": -1, "hidden": hidden,
    }


def text(en, zh):
    return {"en": en, "zh": zh}


NARRATION = [
    {"depth": 0, "text": text("The camera ray meets the glass ball near its top.", "相机光线在球顶附近射中玻璃球。")},
    {"depth": 1, "text": text("At the hit: a shadow ray to the light, a reflected ray and a refracted ray.",
                              "在交点处：一条射向光源的阴影光线、一条反射光线和一条折射光线。")},
    {"depth": 2, "text": text("Inside the glass the refracted ray leaves the ball and bends away from the normal.",
                              "折射光线穿过玻璃、离开球体时偏离法线。")},
    {"depth": 3, "text": text("On the floor the shadow ray is blocked by the ball: that point is in shadow.",
                              "地面上的阴影光线被球挡住：该点处于阴影中。")},
]


def lesson(phrases):
    steps = [
        {"title": text("One ray, a whole tree", "一条光线，一整棵树"),
         "text": text("The camera ray splits at the glass ball into a reflected and a refracted ray.\n\n"
                      "Drag the view to turn it; move the slider to grow the tree depth by depth.",
                      "相机光线在玻璃球处分成反射光线和折射光线。\n\n拖动视图可以旋转；拖动滑块可以逐层展开光线树。"),
         "notes": text("Ask the class to count the rays before moving the slider.", "先让学生数一数光线，再拖动滑块。"),
         "layout": "scene", "pictures": [], "view3d": view3d(phrases), "narration": NARRATION,
         "question": {"type": "number", "predict": False,
                      "prompt": text("How many rays does this tree hold?", "这棵光线树共有多少条光线？"),
                      "choices": [], "answer": 7, "tolerance": 0,
                      "hint": text("Count the shadow rays too.", "阴影光线也要算上。"),
                      "explanation": text("One camera ray, two refracted, two reflected and two shadow rays: 7.",
                                          "一条相机光线、两条折射光线、两条反射光线和两条阴影光线，共 7 条。")}},
        {"title": text("Predict the refraction", "预测折射方向"),
         "text": text("Before you see the tree: where does the refracted ray go?", "先别看光线树：折射光线往哪里走？"),
         "notes": None, "layout": "scene", "pictures": [], "view3d": view3d(phrases, hidden=True), "narration": NARRATION,
         "question": {"type": "choice", "predict": True,
                      "prompt": text("Entering the glass, the ray bends", "光线进入玻璃时"),
                      "choices": [text("away from the normal", "偏离法线"), text("towards the normal", "偏向法线"),
                                  text("not at all", "不发生偏折")],
                      "answer": 1, "tolerance": None, "hint": text("Glass is optically denser than air.", "玻璃是光密介质。"),
                      "explanation": text("Light slows down in glass, so it bends towards the normal (Snell's law).",
                                          "光在玻璃中变慢，所以偏向法线（斯涅尔定律）。")}},
        {"title": text("The rendered image", "渲染结果"),
         "text": text("Every pixel of this image ran a tree like the one you just grew.", "这幅图像的每个像素都生长出一棵这样的光线树。"),
         "notes": None, "layout": "image",
         "pictures": [{"src": text("04-whitted/s02-en.png", "04-whitted/s02-zh.png"),
                       "alt": text("The Whitted scene rendered", "Whitted 场景的渲染结果")}],
         "view3d": None, "narration": [], "question": None},
        {"title": text("Depth one", "第一层"),
         "text": text("The tree opens at depth 1: only the camera ray and its children.", "光线树从第 1 层开始显示：只有相机光线和它的子光线。"),
         "notes": None, "layout": "scene", "pictures": [], "view3d": view3d(phrases, reveal=1), "narration": NARRATION,
         "question": None},
    ]
    for i, step in enumerate(steps):
        step["index"] = i
        step.setdefault("caption", text("", ""))
        step.setdefault("inspector", text("", ""))
    return {"id": "04-whitted", "title": text("Whitted ray tracing", "Whitted 光线追踪"),
            "summary": text("Recursive rays at mirrors and glass.", "镜面与玻璃处的递归光线。"),
            "objectives": [text("Trace Whitted's recursion by hand.", "手工追踪 Whitted 的递归。")], "steps": steps}


def script(call, value):
    body = json.dumps(value, ensure_ascii=False, separators=(",", ":"))
    for raw, escaped in (("<", "\\u003c"), (">", "\\u003e"), ("&", "\\u0026"), ("\u2028", "\\u2028"), ("\u2029", "\\u2029")):
        body = body.replace(raw, escaped)
    return f"RayLabSite.{call}({body});\n"


def shell(page, lesson_id=None):
    up = "../" if lesson_id else ""
    data = f' data-lesson="{lesson_id}"' if lesson_id else ""
    extra = f'\n<script src="{lesson_id}.js"></script>' if lesson_id else ""
    return (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
            f'<meta name="viewport" content="width=device-width, initial-scale=1">\n<title>RayLab</title>\n'
            f'<link rel="stylesheet" href="{up}raylab-web.css">\n</head>\n<body>\n'
            f'<div id="raylab-app" data-page="{page}"{data}><noscript>This page needs JavaScript. '
            f'本页面需要 JavaScript。</noscript></div>\n'
            f'<script src="{up}raylab-web.js"></script>\n<script src="{up}course.js"></script>{extra}\n</body>\n</html>\n')


def main():
    table = json.loads(Path(sys.argv[1]).read_text(encoding="utf-8"))
    table = table.get("phrases", table)
    phrases = {k: v for k, v in table.items() if k.startswith(("web.", "ray_kind.", "end_reason."))}
    phrases.setdefault("web.language_name", text("English", "中文"))
    out = Path(sys.argv[2])
    (out / "lessons" / "04-whitted").mkdir(parents=True, exist_ok=True)
    the_lesson = lesson(phrases)
    course = {"version": 1, "student": False, "languages": ["en", "zh"], "defaultLanguage": "en", "phrases": phrases,
              "lessons": [{"id": "04-whitted", "page": "lessons/04-whitted.html", "title": the_lesson["title"],
                           "summary": the_lesson["summary"], "steps": len(the_lesson["steps"]), "minutes": 12}]}
    (out / "course.js").write_text(script("course", course), encoding="utf-8")
    (out / "lessons" / "04-whitted.js").write_text(script("lesson", the_lesson), encoding="utf-8")
    (out / "index.html").write_text(shell("index"), encoding="utf-8")
    (out / "lessons" / "04-whitted.html").write_text(shell("lesson", "04-whitted"), encoding="utf-8")
    picture = HERE.parent / "baselines" / "TestRayTreeView_whitted.png"
    for lang in ("en", "zh"):
        shutil.copyfile(picture, out / "lessons" / "04-whitted" / f"s02-{lang}.png")


if __name__ == "__main__":
    main()
