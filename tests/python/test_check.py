"""raylab check (issue 35): every exercise's reference solution passes, every typical bug
fails with its name in the report, and student code that hangs, allocates without end,
crashes or raises is reported within the limits, in a child process."""

import json
import os
import subprocess
import sys
import textwrap
import time

import pytest

SOURCE = os.environ.get("RAYLAB_SOURCE_DIR",
                        os.path.join(os.path.dirname(__file__), "..", ".."))
EXERCISES = os.path.join(SOURCE, "exercises")
NAMES = sorted(d for d in os.listdir(EXERCISES)
               if os.path.isfile(os.path.join(EXERCISES, d, "exercise.json")))


def check(exercise, path, tmp_path, *extra):
    """Runs raylab check as a student would; returns (exit status, report.json, stdout)."""
    out = tmp_path / "report"
    env = dict(os.environ, RAYLAB_EXERCISES=EXERCISES)
    command = [sys.executable, "-m", "raylab.check", exercise, str(path), "--out", str(out),
               *extra]
    if os.environ.get("RAYLAB_EXE"):
        command = [os.environ["RAYLAB_EXE"], "check", exercise, str(path), "--out", str(out),
                   *extra]
    done = subprocess.run(command, env=env, capture_output=True, text=True, timeout=120)
    report = None
    if (out / "report.json").exists():
        report = json.loads((out / "report.json").read_text())
    return done.returncode, report, done.stdout + done.stderr


def student_file(tmp_path, text):
    path = tmp_path / "student.py"
    path.write_text(textwrap.dedent(text))
    return path


def test_01_at_least_eight_exercises_with_bilingual_instructions_and_a_lesson():
    assert len(NAMES) >= 8
    for name in NAMES:
        folder = os.path.join(EXERCISES, name)
        meta = json.load(open(os.path.join(folder, "exercise.json"), encoding="utf-8"))
        lesson_file = os.path.join(SOURCE, meta["lesson"]["file"])
        assert os.path.isfile(lesson_file), name
        # The step the exercise links to is the one it names (lessons get renumbered and split).
        steps = json.load(open(lesson_file, encoding="utf-8"))["steps"]
        step = meta["lesson"]["step"]
        assert 1 <= step <= len(steps), name
        assert steps[step - 1]["title"]["en"] == meta["lesson"]["title"], name
        for readme in ("README.md", "README.zh.md"):
            text = open(os.path.join(folder, readme), encoding="utf-8").read()
            assert os.path.basename(meta["lesson"]["file"])[:-5] in text, (name, readme)
        zh = open(os.path.join(folder, "README.zh.md"), encoding="utf-8").read()
        assert any("\u4e00" <= ch <= "\u9fff" for ch in zh)
        starter = open(os.path.join(folder, "starter.py"), encoding="utf-8").read()
        assert "def %s(" % meta["function"] in starter and "TODO" in starter
        assert meta["bugs"], name


@pytest.mark.parametrize("name", NAMES)
def test_02_the_reference_solution_passes_every_case(name, tmp_path):
    code, report, text = check(name, os.path.join(EXERCISES, name, "solution.py"), tmp_path)
    assert code == 0, text
    assert report["passes"] and report["cases"]
    assert all(c["verdict"] == "agrees" or c["verdict"] == "off_by_ulps"
               for c in report["cases"]), text
    if name in GEOMETRY:  # a pixel's tree traced with the solution: every ray agrees
        assert report["tree"]["first_divergent"] == -1, text


GEOMETRY = ("01-intersect-sphere", "02-intersect-plane", "03-intersect-box",
            "04-intersect-triangle")

BUGS = [(name, bug["name"]) for name in NAMES
        for bug in json.load(open(os.path.join(EXERCISES, name, "exercise.json"),
                                  encoding="utf-8"))["bugs"]]


@pytest.mark.parametrize("name,bug", BUGS)
def test_03_each_typical_bug_fails_and_is_named(name, bug, tmp_path):
    code, report, text = check(name, os.path.join(EXERCISES, name, "bugs", bug + ".py"),
                               tmp_path)
    assert code == 1, text
    assert not report["passes"]
    assert [b["name"] for b in report["bugs"]] == [bug], text
    assert report["first_divergent"]["case"] in text
    assert "Known bug" in text and "常见错误" in text


def test_03b_a_wrong_root_shows_its_first_divergent_ray_in_a_traced_tree(tmp_path):
    code, report, text = check("01", os.path.join(EXERCISES, "01-intersect-sphere", "bugs",
                                                   "wrong_root.py"), tmp_path)
    tree = report["tree"]
    assert tree["first_divergent"] == 0 and tree["verdicts"][0] == "wrong_hit"
    assert tree["call"]["student"] > tree["call"]["reference"]
    assert "First divergent ray" in text and "第一条出错的光线" in text


def test_04_the_starter_fails_with_its_todo(tmp_path):
    code, report, text = check("01", os.path.join(EXERCISES, "01-intersect-sphere",
                                                   "starter.py"), tmp_path)
    assert code == 1
    assert report["cases"][0]["verdict"] == "exception"
    assert "NotImplementedError" in report["cases"][0]["error"]


def test_05_an_endless_loop_is_stopped_at_the_time_limit(tmp_path):
    path = student_file(tmp_path, """
        def reflect(d, n):
            while True:
                pass
        """)
    start = time.monotonic()
    code, report, text = check("05-reflect", path, tmp_path, "--time-limit", "3")
    assert time.monotonic() - start < 30
    assert code == 1 and report["problem"]["kind"] == "timeout", text
    assert "3 s" in text and "死循环" in text


def test_06_endless_allocation_is_stopped_at_the_memory_limit(tmp_path):
    path = student_file(tmp_path, """
        def reflect(d, n):
            hoard = []
            while True:
                hoard.append(bytearray(50 << 20))
        """)
    code, report, text = check("05-reflect", path, tmp_path, "--memory-limit", "400")
    assert code == 1 and report["problem"]["kind"] == "memory", text
    assert "400 MB" in text


def test_07_a_ctypes_segfault_is_a_crash_in_the_report(tmp_path):
    path = student_file(tmp_path, """
        import ctypes

        def reflect(d, n):
            return ctypes.string_at(0)
        """)
    code, report, text = check("05-reflect", path, tmp_path)
    assert code == 1 and report["problem"]["kind"] == "crash", text
    assert "SIGSEGV" in text


def test_08_an_exception_is_a_verdict_with_the_students_line(tmp_path):
    path = student_file(tmp_path, """
        def reflect(d, n):
            return d / 0 + undefined_name
        """)
    code, report, text = check("05-reflect", path, tmp_path)
    assert code == 1
    case = report["cases"][0]
    assert case["verdict"] == "exception"
    assert "NameError" in case["error"] and "student.py, line 3" in case["error"]


def test_09_unusable_files_name_the_file_the_line_and_what_was_expected(tmp_path):
    path = student_file(tmp_path, """
        def reflect(d, n)
            return d
        """)
    code, report, text = check("05-reflect", path, tmp_path)
    assert code == 1 and report["problem"]["kind"] == "syntax_error"
    assert report["problem"]["line"] == 2 and "student.py" in text and "语法错误" in text
    path = student_file(tmp_path, """
        def reflection(d, n):
            return d
        """)
    code, report, text = check("05-reflect", path, tmp_path)
    assert report["problem"]["kind"] == "missing_function"
    assert "def reflect(d, n) -> vector" in text and "找不到函数" in text
    path = student_file(tmp_path, """
        def reflect(d):
            return d
        """)
    code, report, text = check("05-reflect", path, tmp_path)
    assert report["problem"]["kind"] == "wrong_signature"
    assert report["problem"]["line"] == 2 and "reflect(d, n)" in text and "应当是" in text
    path = student_file(tmp_path, """
        def intersect_sphere(origin, direction, center, radius, t_min, t_max):
            return "4"
        """)
    code, report, text = check("01", path, tmp_path)
    assert code == 1
    assert "expected a float t or None" in report["cases"][0]["error"]


def test_10_unknown_exercise_is_a_usage_error(tmp_path):
    code, _, text = check("99-nothing", os.path.join(EXERCISES, "05-reflect", "solution.py"),
                          tmp_path)
    assert code == 2 and "01-intersect-sphere" in text
