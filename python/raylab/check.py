"""``raylab check EXERCISE STUDENT.py``: grade a student's function on an exercise's cases.

检查学生代码：在子进程中运行学生的函数，逐个用例评判，并写出 Markdown 与 JSON 报告。

The student's code runs in a child process (``raylab._check_child``) with a time limit, a
memory limit (setrlimit) and a temporary working folder: a crash, a hang, an exception or
endless allocation becomes a message in the report. Each case is judged by
``raylab.student.judge``; when the answers match those of a known typical bug of the
exercise (``exercises/NN-name/bugs/*.py``), the report names it.

Exit status: 0 when every case passes, 1 otherwise (or when the file cannot be used), 2 for
a wrong command line (an unknown exercise, a missing file).

    python3 -m raylab.check 01-intersect-sphere my_sphere.py --out report/
"""

import argparse
import json
import math
import os
import resource
import signal
import subprocess
import sys
import tempfile

PASSING = ("agrees", "off_by_ulps", "not_judged")
# What the child gives as JSON text and the report writes as files beside report.json
# (report.json's "tree" names them): key -> file name.
_TREE_FILES = ("scene_json", "student_tree_json", "reference_tree_json")
_TREE_FILE_NAMES = {"scene_json": "scene.json", "student_tree_json": "student-tree.json",
                    "reference_tree_json": "reference-tree.json"}


def exercises_folder():
    """The exercises/ folder: $RAYLAB_EXERCISES, beside the source tree, or installed."""
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = [os.environ.get("RAYLAB_EXERCISES", ""),
                  os.path.join(here, "exercises"),
                  os.path.join(here, "..", "..", "..", "exercises"),
                  os.path.join(here, "..", "..", "exercises"),
                  "/usr/share/raylab/exercises"]
    if os.environ.get("RAYLAB_SOURCE_DIR"):
        candidates.insert(1, os.path.join(os.environ["RAYLAB_SOURCE_DIR"], "exercises"))
    for folder in candidates:
        if folder and os.path.isfile(os.path.join(folder, "README.md")):
            return os.path.normpath(folder)
    raise FileNotFoundError("the exercises folder was not found (set RAYLAB_EXERCISES)")


def load_exercise(name):
    """The exercise named `name` (its folder name, or its number "01"): its exercise.json
    with "folder" added. KeyError naming the exercises otherwise."""
    root = exercises_folder()
    names = sorted(d for d in os.listdir(root)
                   if os.path.isfile(os.path.join(root, d, "exercise.json")))
    chosen = [d for d in names if d == name or d.split("-")[0] == name
              or d.split("-", 1)[-1] == name]
    if len(chosen) != 1:
        raise KeyError("unknown exercise %r: the exercises are %s" % (name, ", ".join(names)))
    folder = os.path.join(root, chosen[0])
    with open(os.path.join(folder, "exercise.json"), encoding="utf-8") as f:
        exercise = json.load(f)
    exercise["folder"] = folder
    exercise["id"] = chosen[0]
    return exercise


def _limits(memory_mb, seconds):
    def apply():
        os.setsid()
        resource.setrlimit(resource.RLIMIT_AS, (memory_mb << 20, memory_mb << 20))
        cpu = int(math.ceil(seconds)) + 1
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
        resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    return apply


def run_child(exercise, student_path, seconds=10.0, memory_mb=1024):
    """Runs the student's file in a child process; returns the child's result dict, or
    {"status": "failed", "problem": {...}} for a crash, a hang or a memory overrun."""
    bugs = [os.path.join(exercise["folder"], "bugs", b["file"]) for b in exercise["bugs"]]
    with tempfile.TemporaryDirectory(prefix="raylab-check-") as work:
        result_path = os.path.join(work, "result.json")
        env = dict(os.environ)
        package_parent = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        env["PYTHONPATH"] = package_parent + os.pathsep + env.get("PYTHONPATH", "")
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        command = [sys.executable, "-m", "raylab._check_child", exercise["piece"],
                   exercise["function"], os.path.abspath(student_path), result_path] + bugs
        child = subprocess.Popen(command, cwd=work, env=env, stdout=subprocess.PIPE,
                                 stderr=subprocess.PIPE, preexec_fn=_limits(memory_mb, seconds))
        try:
            _, err = child.communicate(timeout=seconds)
        except subprocess.TimeoutExpired:
            os.killpg(child.pid, signal.SIGKILL)
            child.communicate()
            return _failed("timeout", student_path,
                           "did not finish within %g s (an endless loop?)" % seconds,
                           "未能在 %g 秒内结束（是否有死循环？）" % seconds)
        err = err.decode("utf-8", "replace")
        if os.path.isfile(result_path):
            with open(result_path, encoding="utf-8") as f:
                result = json.load(f)
            picture = (result.get("tree") or {}).get("picture")
            if picture and os.path.isfile(picture):  # read before the folder goes
                with open(picture, "rb") as f:
                    result["tree"]["png"] = f.read()
            if result.get("problem", {}).get("kind") == "memory":  # MemoryError in the child
                return _failed("memory", student_path,
                               "used more than the %d MB memory limit" % memory_mb,
                               "使用的内存超过了 %d MB 的限制" % memory_mb, "MemoryError")
            return result
        return _crash(child.returncode, err, student_path, memory_mb, seconds)


def _failed(kind, path, en, zh, detail=""):
    return {"status": "failed",
            "problem": {"kind": kind, "file": path, "line": None, "en": en, "zh": zh,
                        "detail": detail}}


def _crash(code, err, path, memory_mb, seconds):
    tail = "\n".join(err.strip().splitlines()[-6:])
    if "MemoryError" in err or code == -signal.SIGKILL:
        return _failed("memory", path, "used more than the %d MB memory limit" % memory_mb,
                       "使用的内存超过了 %d MB 的限制" % memory_mb, tail)
    if code == -signal.SIGXCPU:
        return _failed("timeout", path, "used more than %g s of processor time" % seconds,
                       "占用处理器时间超过 %g 秒" % seconds, tail)
    if code is not None and code < 0:
        name = signal.Signals(-code).name
        return _failed("crash", path, "crashed with %s (e.g. a bad pointer through ctypes)"
                       % name, "进程因 %s 崩溃（例如通过 ctypes 访问了非法指针）" % name, tail)
    return _failed("crash", path, "stopped with exit status %s" % code,
                   "进程以退出码 %s 结束" % code, tail)


def _same_verdicts(a, b):
    return len(a["cases"]) == len(b["cases"]) and all(
        x["verdict"] == y["verdict"] for x, y in zip(a["cases"], b["cases"]))


def _close(x, y):
    """Whether two answers are the same up to rounding (1e-12 relative)."""
    if isinstance(x, list) and isinstance(y, list):
        return len(x) == len(y) and all(_close(a, b) for a, b in zip(x, y))
    if isinstance(x, (int, float)) and isinstance(y, (int, float)):
        if math.isnan(x) or math.isnan(y):
            return math.isnan(x) and math.isnan(y)
        return x == y or abs(x - y) <= 1e-12 * max(abs(x), abs(y))
    return x == y


def _same_values(a, b):
    return all(_close(x.get("student"), y.get("student")) for x, y in zip(a["cases"], b["cases"]))


def name_bugs(exercise, result):
    """The typical bugs whose answers the student's reproduce: the same verdict on every
    case; where several bugs do, those whose answers are also the same values."""
    judgement = result.get("judgement")
    if not judgement or judgement["passes"]:
        return []
    candidates = []
    for bug in exercise["bugs"]:
        path = os.path.join(exercise["folder"], "bugs", bug["file"])
        theirs = result.get("bugs", {}).get(path)
        if theirs and _same_verdicts(judgement, theirs):
            candidates.append((bug, theirs))
    if len(candidates) > 1:
        exact = [c for c in candidates if _same_values(judgement, c[1])]
        candidates = exact or candidates
    return [bug for bug, _ in candidates]


def _value(v):
    if isinstance(v, float):
        return "%.17g" % v
    if isinstance(v, list):
        return "(" + ", ".join(_value(x) for x in v) + ")"
    return "None" if v is None else str(v)


def report(exercise, student_path, result):
    """The report as a dict (what the JSON holds) with `passes` and `markdown`."""
    out = {"exercise": exercise["id"], "piece": exercise["piece"], "file": student_path,
           "status": result["status"], "passes": False, "cases": [], "bugs": [],
           "problem": result.get("problem"), "first_divergent": None}
    lines = ["# raylab check: %s" % exercise["id"], "",
             "%s / %s" % (exercise["title"]["en"], exercise["title"]["zh"]), "",
             "File: `%s`" % student_path, ""]
    if result["status"] != "ran":
        p = result["problem"]
        where = "%s, line %s" % (p["file"], p["line"]) if p.get("line") else p["file"]
        lines += ["**Could not be checked / 无法检查**", "", "- %s: %s" % (where, p["en"]),
                  "- %s：%s" % (where, p["zh"])]
        if p.get("detail"):
            lines += ["", "```", p["detail"], "```"]
        out["markdown"] = "\n".join(lines) + "\n"
        return out
    judgement = result["judgement"]
    out["passes"] = judgement["passes"]
    out["cases"] = judgement["cases"]
    failing = [c for c in judgement["cases"] if c["verdict"] not in PASSING]
    passed = len(judgement["cases"]) - len(failing)
    lines += ["**%s** — %d of %d cases pass / 通过 %d 个用例，共 %d 个" % (
        "PASS" if out["passes"] else "FAIL", passed, len(judgement["cases"]), passed,
        len(judgement["cases"])), "", "| case | verdict | yours | reference |",
        "| --- | --- | --- | --- |"]
    for c in judgement["cases"]:
        lines.append("| %s | %s | %s | %s |" % (c["case"], c["verdict"], _value(c["student"]),
                                               _value(c["reference"])))
    if failing:
        first = failing[0]
        out["first_divergent"] = first
        lines += ["", "## First divergent case / 第一个出错的用例", "",
                  "- case: %s" % first["case"], "- yours / 你的结果: %s" % _value(first["student"]),
                  "- reference / 参考结果: %s" % _value(first["reference"])]
        if first.get("error"):
            lines.append("- error / 错误: %s" % first["error"])
    lines += _tree_lines(result.get("tree"), out)
    if (result.get("tree") or {}).get("png"):
        out["png"] = result["tree"]["png"]
    bugs = name_bugs(exercise, result)
    out["bugs"] = [{"name": b["name"], "en": b["en"], "zh": b["zh"]} for b in bugs]
    for b in bugs:
        lines += ["", "## Known bug: %s / 常见错误：%s" % (b["en"], b["zh"]), "", b["hint_en"],
                  "", b["hint_zh"]]
    out["markdown"] = "\n".join(lines) + "\n"
    return out


def _tree_lines(tree, out):
    """The report's lines about the traced pixel: its first divergent ray and the picture."""
    if not tree:
        return []
    x, y = tree["pixel"]
    lines = ["", "## Your tree / 你的光线树", "",
             "Pixel (%d, %d) of the default scene, Whitted: %d rays / 默认场景像素 (%d, %d)，"
             "Whitted 算法，共 %d 条光线。" % (x, y, len(tree["verdicts"]), x, y,
                                             len(tree["verdicts"]))]
    call = tree.get("call")
    if call:
        lines += ["", "First divergent ray / 第一条出错的光线: #%d (%s)" % (call["ray"],
                                                                          call["verdict"]),
                  "- origin %s, direction %s, t in [%s, %s]" % (
                      _value(call["origin"]), _value(call["direction"]), _value(call["t_min"]),
                      _value(call["t_max"])),
                  "- yours / 你的结果: t = %s; exact / 精确结果: t = %s" % (
                      _value(call["student"]), _value(call["reference"]))]
        if call.get("error"):
            lines.append("- error / 错误: %s" % call["error"])
    else:
        lines += ["", "Every ray agrees / 每条光线都一致。"]
    out["tree"] = {k: v for k, v in tree.items() if k not in ("png", "picture") + _TREE_FILES}
    out["tree_files"] = {}
    for key in _TREE_FILES:
        if tree.get(key):
            out["tree"][key[:-len("_json")]] = _TREE_FILE_NAMES[key]
            out["tree_files"][_TREE_FILE_NAMES[key]] = tree[key]
    if tree.get("png"):
        out["tree"]["picture"] = "tree.png"
        lines += ["", "![Your tree coloured by verdict (left) beside the engine's (right) / "
                      "左：按评判结果着色的你的光线树；右：引擎的光线树](tree.png)"]
    elif tree.get("picture_error") or not tree.get("picture"):
        lines += ["", "(No picture: no display; run under xvfb-run for tree.png / "
                      "没有显示设备，未生成图片。)"]
    return lines


def main(argv=None):
    parser = argparse.ArgumentParser(prog="raylab check", description=__doc__.split("\n")[0])
    parser.add_argument("exercise")
    parser.add_argument("student")
    parser.add_argument("--out", default=None, help="folder for report.md and report.json")
    parser.add_argument("--time-limit", type=float, default=20.0, help="seconds (default 20)")
    parser.add_argument("--memory-limit", type=int, default=1024, help="MB (default 1024)")
    args = parser.parse_args(argv)
    try:
        exercise = load_exercise(args.exercise)
    except (KeyError, FileNotFoundError) as error:
        print("raylab check: %s" % error.args[0], file=sys.stderr)
        return 2
    if not os.path.isfile(args.student):
        print("raylab check: %s: no such file" % args.student, file=sys.stderr)
        return 2
    result = run_child(exercise, args.student, args.time_limit, args.memory_limit)
    r = report(exercise, args.student, result)
    if args.out:
        os.makedirs(args.out, exist_ok=True)
        with open(os.path.join(args.out, "report.md"), "w", encoding="utf-8") as f:
            f.write(r["markdown"])
        with open(os.path.join(args.out, "report.json"), "w", encoding="utf-8") as f:
            json.dump({k: v for k, v in r.items() if k not in ("markdown", "png", "tree_files")},
                      f, indent=1)
        for name, text in r.get("tree_files", {}).items():
            with open(os.path.join(args.out, name), "w", encoding="utf-8") as f:
                f.write(text)
        if r.get("png"):
            with open(os.path.join(args.out, "tree.png"), "wb") as f:
                f.write(r["png"])
    sys.stdout.write(r["markdown"])
    return 0 if r["passes"] else 1


if __name__ == "__main__":
    sys.exit(main())
