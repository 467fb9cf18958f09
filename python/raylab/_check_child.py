"""The child process of ``raylab check``: loads a student's file, runs one piece's cases.

Run as ``python3 -m raylab._check_child PIECE FUNCTION STUDENT.py RESULT.json [BUG.py ...]``
inside a temporary working folder, under the time and memory limits the parent set. Writes
RESULT.json: {"status": "ran", "judgement": ..., "bugs": {name: judgement}} or
{"status": "unusable", "problem": {...}} when the file cannot be used (missing function,
wrong signature: the file, the line and what was expected, in English and Chinese).
"""

import importlib.util
import inspect
import json
import sys


def _load(path, name):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _jsonable(value):
    if value is None or isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, dict):
        return {str(k): _jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_jsonable(v) for v in value]
    try:
        import numpy as np
        if isinstance(value, np.ndarray):
            return [_jsonable(v) for v in value.tolist()]
        if isinstance(value, np.generic):
            return value.item()
    except ImportError:
        pass
    return repr(value)


def main(argv):
    piece, function, student_path, result_path = argv[:4]
    bug_paths = argv[4:]
    from raylab import student
    from raylab._judge import judge

    def write(result):
        with open(result_path, "w", encoding="utf-8") as out:
            json.dump(_jsonable(result), out, indent=1, allow_nan=True)

    try:
        module = _load(student_path, "student_code")
    except SyntaxError as error:
        write({"status": "unusable", "problem": {
            "kind": "syntax_error", "file": student_path, "line": error.lineno,
            "en": "syntax error: %s" % error.msg, "zh": "语法错误：%s" % error.msg}})
        return
    except BaseException as error:  # the student's module-level code
        import traceback
        frames = [f for f in traceback.extract_tb(error.__traceback__)
                  if f.filename == student_path]
        line = frames[-1].lineno if frames else None
        write({"status": "unusable", "problem": {
            "kind": "import_error", "file": student_path, "line": line,
            "en": "the file raised %s: %s while loading" % (type(error).__name__, error),
            "zh": "加载文件时抛出 %s：%s" % (type(error).__name__, error)}})
        return
    params, returns, _, _ = student.PIECES[piece]
    expected = "%s(%s) -> %s" % (function, ", ".join(params), returns)
    fn = getattr(module, function, None)
    if fn is None:
        write({"status": "unusable", "problem": {
            "kind": "missing_function", "file": student_path, "line": None,
            "en": "no function %s: expected def %s" % (function, expected),
            "zh": "找不到函数 %s：应当定义 def %s" % (function, expected)}})
        return
    try:
        student._check_signature(piece, fn)
    except student.StudentCodeError:
        line = getattr(getattr(fn, "__code__", None), "co_firstlineno", None)
        got = ", ".join(inspect.signature(fn).parameters) if callable(fn) else repr(fn)
        write({"status": "unusable", "problem": {
            "kind": "wrong_signature", "file": student_path, "line": line,
            "en": "%s takes (%s); expected %s" % (function, got, expected),
            "zh": "%s 的参数是 (%s)；应当是 %s" % (function, got, expected)}})
        return
    try:
        result = {"status": "ran", "judgement": judge(piece, fn), "bugs": {}}
    except MemoryError:
        write({"status": "failed", "problem": {
            "kind": "memory", "file": student_path, "line": None,
            "en": "used more than the memory limit (MemoryError)",
            "zh": "使用的内存超过了限制（MemoryError）"}})
        return
    for path in bug_paths:
        bug = _load(path, "bug_code")
        result["bugs"][path] = judge(piece, getattr(bug, function))
    if piece in student.GEOMETRY:
        result["tree"] = _tree(piece, fn)
    write(result)


def _tree(piece, fn):
    """The student's tree of a pixel of the default scene (with a plane or a triangle added
    for those pieces): the first pixel of a 16 x 12 grid whose tree diverges, else the first
    whose camera ray the piece answers; its first divergent ray with both values, and, with
    a display, tree.png (the student's tree by verdict beside the engine's) in the working
    folder."""
    import os
    import raylab
    from raylab import student
    scene = raylab.default_scene()
    if piece in ("intersect_plane", "intersect_triangle"):
        scene.add_shape(piece.split("_")[1])
    width, height = scene.size
    student.use(**{piece: fn})
    chosen = None
    for j in range(12):
        for i in range(16):
            pixel = (int((i + 0.5) * width / 16), int((j + 0.5) * height / 12))
            t = student.trace(scene, pixel, algorithm="whitted")
            if not t.passes:
                chosen = (pixel, t)
                break
            if chosen is None and any(c["piece"] == piece and c["ray"] == 0
                                      and c["reference"] is not None for c in t.calls):
                chosen = (pixel, t)
        if chosen and not chosen[1].passes:
            break
    if chosen is None:
        return None
    pixel, t = chosen
    out = {"pixel": list(pixel), "algorithm": "whitted", "verdicts": t.verdicts,
           "first_divergent": t.first_divergent, "picture": None,
           # The scene and both trees as RayLab's JSON (doc/ray-tree-json.md), for the
           # window's Lessons > Check my code, which draws them itself.
           "scene_json": scene.to_json(), "student_tree_json": t.student.to_json(),
           "reference_tree_json": t.reference.to_json()}
    if t.first_divergent >= 0:
        out["call"] = t.calls[t.deciding_calls[t.first_divergent]]
    if os.environ.get("DISPLAY"):
        try:
            student.save_view("tree.png", scene, t, width=400, height=300)
            out["picture"] = os.path.abspath("tree.png")
        except Exception as error:  # no usable display: the report says so
            out["picture_error"] = str(error)
    return out


if __name__ == "__main__":
    main(sys.argv[1:])
