#!/usr/bin/env python3
"""Checks of `raylab web` (issue 34; doc/web-data.md), one per CTest test:

  WebExport.py CHECK RAYLAB_EXE SOURCE_DIR WORK_DIR [WITH_DISPLAY]

CHECK is one of: course (every step of every lesson exported, in both languages; every 3D
step's tree equal to `raylab trace --lesson`'s, 3D steps without a traced pixel with no tree),
rays (lesson 4's 3D steps' rays equal `raylab trace --lesson --json`'s tree, and plain
`raylab trace --pixel`'s where the step changes nothing: count, ids, kinds, depths, end
reasons, end points to 1e-6, hits; the bug-hunt step 16's verdicts against the correct
engine's tree), hostile (a lesson's title `</script><script>...` and
names with quotes stay text), survive (an export that fails leaves the old site intact,
names what failed, exits 1), student (--student: no notes, no answer key), bounded
(--max-size refuses a site beyond it), interrupt (Ctrl-C leaves the old site), fulldisk (a
full tmpfs leaves the old site; skipped, exit 77, where no tmpfs can be mounted)."""
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time

CHECK, RAYLAB, SOURCE, WORK = sys.argv[1:5]
DISPLAY = sys.argv[5:6]  # the with-display wrapper, when given
LESSONS = os.path.join(SOURCE, "lessons")


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(args, code=0):
    result = subprocess.run(DISPLAY + [RAYLAB] + args, capture_output=True, text=True)
    if result.returncode != code:
        fail("raylab %s: exit %d (expected %d)\nstdout: %s\nstderr: %s" %
             (" ".join(args), result.returncode, code, result.stdout, result.stderr))
    return result


def bundle():
    """A stand-in bundle (the real one is tested by tests/web): the export copies it."""
    folder = os.path.join(WORK, "web-bundle")
    os.makedirs(folder, exist_ok=True)
    for name, text in (("raylab-web.js", "window.RayLabSite = {};\n"), ("raylab-web.css", "")):
        with open(os.path.join(folder, name), "w") as f:
            f.write(text)
    return ["--bundle", folder]


def load_call(path, function):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    prefix = "RayLabSite.%s(" % function
    if not text.startswith(prefix) or not text.endswith(");\n"):
        fail("%s: not one call of %s" % (path, prefix))
    return text, json.loads(text[len(prefix):-3])


def export(out, *args, code=0):
    shutil.rmtree(out, ignore_errors=True)
    return run(["web", "--out", out, "--max-spp", "1"] + bundle() + list(args), code)


def lesson_trees(lesson_file):
    """`raylab trace --lesson FILE --step all --json`: every step's tree as the lesson stager
    traces it (null, with why, where the step traces none), in one process, no display."""
    dump = os.path.join(WORK, "web-lesson-trees.json")
    result = subprocess.run([RAYLAB, "trace", "--lesson", lesson_file, "--step", "all",
                             "--json", dump], capture_output=True, text=True)
    if result.returncode != 0:
        fail("raylab trace --lesson %s --step all: exit %d\n%s" %
             (lesson_file, result.returncode, result.stderr))
    with open(dump, encoding="utf-8") as f:
        return json.load(f)["steps"]


def compare_tree(where, view, segments):
    """The exported rays and hits of one step against the dump's segments: ids, parents,
    kinds, depths, end reasons, hit flags, end points to 1e-6, the hits' points."""
    rays = view["rays"]
    if len(rays) != len(segments):
        fail("%s: %d rays exported, trace has %d" % (where, len(rays), len(segments)))
    for ray, seg in zip(rays, segments):
        if (ray["id"], ray["parent"], ray["kind"], ray["depth"], ray["ends"], ray["hit"]) != \
           (seg["id"], seg["parent"], seg["kind"], seg["depth"], seg["end_reason"], seg["hit"]):
            fail("%s: ray %d differs: %s against %s" % (where, ray["id"], ray, seg))
        for a, b in zip(ray["origin"] + ray["end"], seg["origin"] + seg["end_point"]):
            if abs(a - b) > 1e-6:
                fail("%s: ray %d's ends differ by %g" % (where, ray["id"], abs(a - b)))
    hits = [s for s in segments if s["hit"]]
    if [h["ray"] for h in view["hits"]] != [s["id"] for s in hits]:
        fail("%s: the exported hits are rays %s, trace's %s" %
             (where, [h["ray"] for h in view["hits"]], [s["id"] for s in hits]))
    for h, s in zip(view["hits"], hits):
        if max(abs(a - b) for a, b in zip(h["point"], s["end_point"])) > 1e-6:
            fail("%s: hit of ray %d is elsewhere" % (where, s["id"]))


WHY = {}  # why 3D steps trace no tree (trace --lesson's words): how many


def compare_rays(out, lesson_id):
    """Every exported 3D step of `lesson_id` against `raylab trace --lesson`: a step with a
    tree has the same rays; a step the stager traces nothing for exports no rays. Returns
    (counts, lesson, source): counts of 3D steps compared, 3D steps without a traced pixel
    (checked to have no tree), steps without a 3D view (pictures)."""
    _, lesson = load_call(os.path.join(out, "lessons", lesson_id + ".js"), "lesson")
    lesson_file = os.path.join(LESSONS, lesson_id + ".json")
    with open(lesson_file, encoding="utf-8") as f:
        source = json.load(f)
    if len(lesson["steps"]) != len(source["steps"]):
        fail("%s: %d steps exported, the lesson has %d" %
             (lesson_id, len(lesson["steps"]), len(source["steps"])))
    traced = lesson_trees(lesson_file)
    counts = {"compared": 0, "untraced": 0, "pictures": 0}
    for step, trace in zip(lesson["steps"], traced):
        view = step["view3d"]
        where = "%s step %d" % (lesson_id, step["index"] + 1)
        if trace["step"] != step["index"] + 1:
            fail("%s: trace --lesson answered step %d" % (where, trace["step"]))
        if view is None:
            counts["pictures"] += 1
            continue
        # (The samples view shows a sampler's directions alone, as the window does.)
        if step["layout"] != "samples" and (not view["objects"] or
                                             not any(e["kind"] == "camera" for e in view["extras"])):
            fail("%s: no objects or no camera glyph exported" % where)
        if trace["tree"] is None:
            if view["rays"] or view["hits"] or view["trace"]["pixel"] is not None:
                fail("%s: rays exported, but the step traces none (%s)" % (where, trace["why"]))
            counts["untraced"] += 1
            WHY[trace["why"]] = WHY.get(trace["why"], 0) + 1
            continue
        compare_tree(where, view, trace["tree"]["segments"])
        counts["compared"] += 1
    return counts, lesson, source


def compare_plain_trace(out, lesson_id, source, lesson):
    """The steps that change nothing (no scene change, value, chosen ray or bundle) also
    against plain `raylab trace --scene --pixel`: the stager traces what the engine does."""
    scene = os.path.join(LESSONS, source["scene"])
    compared = 0
    for step, written in zip(lesson["steps"], source["steps"]):
        view = step["view3d"]
        if view is None or view["trace"]["pixel"] is None or view["trace"]["bundle"] > 1 or \
           any(k in written for k in ("scene_changes", "try_value", "ray")):
            continue
        trace = view["trace"]
        dump = os.path.join(WORK, "web-rays-step.json")
        run(["trace", "--scene", scene, "--algorithm", trace["algorithm"], "--pixel",
             str(trace["pixel"][0]), str(trace["pixel"][1]), "--sample", str(trace["sample"]),
             "--json", dump, "--out", os.path.join(WORK, "web-rays-step.png"),
             "--size", "160x120"])
        with open(dump) as f:
            compare_tree("%s step %d (plain trace)" % (lesson_id, step["index"] + 1), view,
                         json.load(f)["segments"])
        compared += 1
    return compared


def check_verdicts(lesson, source):
    """The bug-hunt step (lesson 4 step 16, Schlick with the wrong sign) carries the correct
    engine's tree and its own tree's verdicts: the camera ray agrees, the reflected ray
    (ray #1) has the right geometry and the wrong weight (1, not 0.04); steps without a
    fault carry none, and the fault's name (the answer) is not in the data."""
    faulty = [i for i, s in enumerate(source["steps"]) if "fault" in s]
    if faulty != [15]:
        fail("lesson 4's bug-hunt steps are %s, expected step 16 alone" % [i + 1 for i in faulty])
    for step in lesson["steps"]:
        view = step["view3d"]
        if view is not None and step["index"] != 15 and view.get("verdicts") is not None:
            fail("step %d has no fault but exports verdicts" % (step["index"] + 1))
    view = lesson["steps"][15]["view3d"]
    verdicts = view.get("verdicts")
    if not verdicts:
        fail("step 16 (a fault) exports no verdicts")
    names, reference = verdicts["verdict"], verdicts["reference"]
    if len(names) != len(view["rays"]) or len(verdicts["colors"]) != len(view["rays"]):
        fail("step 16: %d verdicts, %d colours for %d rays" %
             (len(names), len(verdicts["colors"]), len(view["rays"])))
    if names[0] != "agrees" or names[1] != "wrong_weight":
        fail("step 16: camera ray %s, reflected ray %s (expected agrees, wrong_weight)" %
             (names[0], names[1]))
    if view["rays"][1]["kind"] != "reflection" or reference[1]["kind"] != "reflection":
        fail("step 16: ray 1 is not the reflected ray in both trees")
    if len(reference) <= len(view["rays"]) or not any(r["kind"] == "refraction" for r in reference):
        fail("step 16: the correct tree (%d rays) lacks the refracted ray the fault loses "
             "(faulty tree %d rays)" % (len(reference), len(view["rays"])))
    labels = [e["label"]["en"] for e in verdicts["legend"]]
    if "wrong weight" not in labels or "agrees" not in labels:
        fail("step 16: the verdict legend says %s" % labels)
    if "schlick" in json.dumps(verdicts).lower():
        fail("step 16: the fault's name (the answer) is in the verdict data")
    print("step 16: verdicts %s; the correct tree has %d rays, the faulty %d" %
          (names, len(reference), len(view["rays"])))


def check_rays():
    out = os.path.join(WORK, "web-rays")
    lesson_id = "04-whitted"
    export(out, "--lang", "en", lesson_id)
    counts, lesson, source = compare_rays(out, lesson_id)
    plain = compare_plain_trace(out, lesson_id, source, lesson)
    if counts["compared"] < 8 or plain < 5:
        fail("only %d steps compared with trace --lesson, %d with plain trace" %
             (counts["compared"], plain))
    check_verdicts(lesson, source)
    # A question's hint (said with "try again", issue 33.6) reaches the page.
    hinted = 0
    for step, written in zip(lesson["steps"], source["steps"]):
        hint = written.get("question", {}).get("hint")
        if hint:
            got = step["question"]["hint"]
            if not got or got.get("en") != hint["en"]:
                fail("step %d: the question's hint is not exported (%r)" % (step["index"] + 1, got))
            hinted += 1
    if hinted == 0:
        fail("lesson 4 has no question with a hint to check")
    print("%d 3D steps' trees equal raylab trace --lesson's (%d of them also plain trace's); "
          "%d 3D steps trace nothing and export no tree" %
          (counts["compared"], plain, counts["untraced"]))


def hostile_lesson():
    folder = os.path.join(WORK, "web-hostile-lessons")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(os.path.join(LESSONS, "03-ray-casting.json"), encoding="utf-8") as f:
        lesson = json.load(f)
    lesson["id"] = "99-hostile"
    lesson["title"] = {"en": "</script><script>alert(1)</script> \"quoted\" 'single'",
                       "zh": "课程<img src=x onerror=alert(2)>"}
    lesson["steps"] = lesson["steps"][:2]
    lesson["steps"][0]["title"] = {"en": "\"quoted\" & <b>bold</b> \u2029", "zh": "'单引号' <i>斜体</i>"}
    lesson["scene"] = os.path.join(LESSONS, lesson["scene"])
    with open(os.path.join(folder, "99-hostile.json"), "w", encoding="utf-8") as f:
        json.dump(lesson, f, ensure_ascii=False)
    return folder


def check_course():
    """Every step of every shipped lesson is in the site, in both languages, and every 3D
    step's tree equals `raylab trace --lesson`'s (scene changes, tried values, chosen rays
    and bundles included); 3D steps without a traced pixel export no tree."""
    out = os.path.join(WORK, "web-course")
    started = time.time()
    export(out)
    exported = time.time() - started
    _, course = load_call(os.path.join(out, "course.js"), "course")
    shipped = sorted(f[:-5] for f in os.listdir(LESSONS) if re.match(r"[0-9]{2}-.*\.json$", f))
    listed = [entry["id"] for entry in course["lessons"]]
    if listed != shipped:
        fail("the course lists %s, the lessons folder has %s" % (listed, shipped))
    total = {"compared": 0, "untraced": 0, "pictures": 0}
    steps = 0
    for lesson_id in shipped:
        counts, lesson, _ = compare_rays(out, lesson_id)
        for step in lesson["steps"]:
            if not step["title"].get("en") or not step["title"].get("zh"):
                fail("%s step %d: a title is missing in one language" %
                     (lesson_id, step["index"] + 1))
            # Words under a picture or view (a capped spp, a mesh's search speed, the
            # inspector) in both languages or in neither.
            for key in ("caption", "inspector"):
                if bool(step[key]["en"]) != bool(step[key]["zh"]):
                    fail("%s step %d: the %s is in one language only: %s" %
                         (lesson_id, step["index"] + 1, key, step[key]))
        steps += len(lesson["steps"])
        for key in total:
            total[key] += counts[key]
    if total["compared"] == 0 or sum(total.values()) != steps:
        fail("steps unaccounted for: %s of %d" % (total, steps))
    print("%d lessons, %d steps: %d 3D steps' trees equal raylab trace --lesson's, %d 3D steps "
          "trace no pixel (no tree exported), %d picture steps; export %.0f s, checks %.0f s" %
          (len(shipped), steps, total["compared"], total["untraced"], total["pictures"],
           exported, time.time() - started - exported))
    for why, count in sorted(WHY.items()):
        print("  %d 3D steps without a tree: %s" % (count, why))


def check_hostile():
    out = os.path.join(WORK, "web-hostile")
    export(out, "--dir", hostile_lesson())
    pages = os.listdir(os.path.join(out, "lessons"))
    scripts = [p for p in pages if p.endswith(".js")]
    if len(scripts) != 1 or not re.fullmatch(r"[A-Za-z0-9_-]+\.js", scripts[0]):
        fail("the lesson's file name is not made safe: %s" % pages)
    for path in [os.path.join(out, "course.js"), os.path.join(out, "lessons", scripts[0])]:
        text, data = load_call(path, "course" if path.endswith("course.js") else "lesson")
        for bad in ("<", ">", "&", "\u2028", "\u2029"):
            if bad in text:
                fail("%s: %r written raw" % (path, bad))
        if "</script><script>alert(1)</script>" not in json.dumps(data):
            fail("%s: the title did not come back as the same text" % path)
    html = open(os.path.join(out, "lessons", scripts[0][:-3] + ".html"), encoding="utf-8").read()
    if "<script>alert" in html or "alert(1)</script>" in html:
        fail("the lesson's page has the title's markup raw:\n" + html)
    if "&lt;/script&gt;" not in html:
        fail("the page's <title> is not the escaped title:\n" + html)
    print("hostile lesson stays text")


def check_survive():
    out = os.path.join(WORK, "web-survive")
    export(out, "--lang", "en", "03-ray-casting")
    marker = os.path.join(out, "index.html")
    before = open(marker, encoding="utf-8").read()
    listing = sorted(os.listdir(os.path.join(out, "lessons")))
    # A failing step (a site beyond --max-size), then a lesson that does not exist.
    result = run(["web", "--out", out, "--max-size", "1", "--lang", "zh"] + bundle(), code=1)
    if not re.search(r"raylab: error: .*(lesson|\.png|\.js).*larger than 1 MB", result.stderr):
        fail("the message does not name what failed: " + result.stderr)
    result = run(["web", "--out", out] + bundle() + ["no-such-lesson"], code=1)
    if "no-such-lesson" not in result.stderr:
        fail("the message does not name the missing lesson: " + result.stderr)
    if open(marker, encoding="utf-8").read() != before or \
       sorted(os.listdir(os.path.join(out, "lessons"))) != listing:
        fail("the old site changed")
    leftovers = [n for n in os.listdir(WORK) if n.startswith(".web-survive") or
                 (n.startswith("web-survive") and n != "web-survive")]
    if leftovers:
        fail("half-written folders left: %s" % leftovers)
    print("old site intact after two failed exports")


def check_student():
    out = os.path.join(WORK, "web-student")
    export(out, "--student", "04-whitted", "08-four-side-by-side")
    text = ""
    for name in os.listdir(os.path.join(out, "lessons")):
        if name.endswith(".js"):
            text_one, lesson = load_call(os.path.join(out, "lessons", name), "lesson")
            text += text_one
            for step in lesson["steps"]:
                q = step["question"]
                if step["notes"] is not None or (q and (q["answer"] is not None or
                   q["explanation"] is not None or q["tolerance"] is not None)):
                    fail("%s step %d: a note or the key is in the student's site" %
                         (name, step["index"] + 1))
    source = json.load(open(os.path.join(LESSONS, "04-whitted.json"), encoding="utf-8"))
    for step in source["steps"]:
        for key in ("teacher_notes", "notes"):
            note = step.get(key)
            if note and json.dumps(note["en"])[1:-1][:40] in text:
                fail("a teacher's note is in the student's site: " + note["en"][:40])
    _, course = load_call(os.path.join(out, "course.js"), "course")
    if course["student"] is not True:
        fail("course.student is not true")
    print("student site without notes and key")


def check_bounded():
    out = os.path.join(WORK, "web-bounded")
    result = export(out, "--lang", "en", "04-whitted", "--zip")
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(out) for f in fs)
    if size > 30 * 1024 * 1024:
        fail("one lesson's site is %d bytes" % size)
    zipped = subprocess.run(["unzip", "-l", out + ".zip"], capture_output=True, text=True).stdout
    for name in ("imsmanifest.xml", "index.html", "course.js", "lessons/04-whitted.js"):
        if name not in zipped:
            fail("%s is not in the zip" % name)
    manifest = open(os.path.join(out, "imsmanifest.xml"), encoding="utf-8").read()
    if 'href="index.html"' not in manifest or "imscp_v1p1" not in manifest:
        fail("imsmanifest.xml is not an IMS CP 1.1 manifest")
    result = export(out, "--lang", "en", "04-whitted", "--max-size", "1", code=1)
    if "larger than 1 MB" not in result.stderr:
        fail("--max-size 1: the message does not say why: " + result.stderr)
    if os.path.exists(out):
        fail("--max-size 1: a site was written")
    print("one lesson: %d bytes; zip with manifest; --max-size 1 refused" % size)


def old_site(out):
    """A stand-in earlier site (files with the names a site has)."""
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(os.path.join(out, "lessons"))
    for name in ("index.html", "course.js"):
        with open(os.path.join(out, name), "w") as f:
            f.write("old " + name)
    return lambda: all(open(os.path.join(out, n)).read() == "old " + n
                       for n in ("index.html", "course.js")) and \
        os.listdir(os.path.join(out, "lessons")) == []


def raylab_below(root):
    """The raylab process started by `root` (itself or a descendant), or None."""
    parents = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = open("/proc/%s/stat" % entry).read()
                parents[int(entry)] = int(stat[stat.rindex(")") + 2:].split()[1])
            except (OSError, ValueError):
                pass
    for pid in sorted(parents):
        p = pid
        while p > 1 and p != root:
            p = parents.get(p, 0)
        if p != root:
            continue
        try:
            name = open("/proc/%d/cmdline" % pid).read().split("\0")[0]
        except OSError:
            continue
        if os.path.basename(name) == "raylab":
            return pid
    return None


def check_interrupt():
    top = os.path.join(WORK, "web-interrupt")
    shutil.rmtree(top, ignore_errors=True)
    out = os.path.join(top, "site")
    intact = old_site(out)
    child = subprocess.Popen(DISPLAY + [RAYLAB, "web", "--out", out, "--max-spp", "1"] + bundle(),
                             stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    for _ in range(1200):  # until the new folder holds a lesson (at most two minutes)
        news = [n for n in os.listdir(top) if n != "site"]
        if news and any(f.endswith(".js") for f in
                        os.listdir(os.path.join(top, news[0], "lessons")) if
                        os.path.isdir(os.path.join(top, news[0], "lessons"))):
            break
        time.sleep(0.1)
    else:
        child.kill()
        fail("no lesson written into a new folder")
    # The display wrapper (xvfb-run) passes no signal on: signal raylab itself.
    target = raylab_below(child.pid)
    if target is None:
        child.kill()
        fail("raylab's process not found")
    os.kill(target, signal.SIGINT)
    _, err = child.communicate(timeout=120)
    if "raylab: interrupted: %s was not changed" % out not in err:
        fail("no message on Ctrl-C: " + err)
    if not intact():
        fail("the old site changed")
    if os.listdir(top) != ["site"]:
        print("left beside the site after Ctrl-C: %s" % os.listdir(top))
    # The next export replaces the site whole and leaves nothing beside it.
    run(["web", "--out", out, "--max-spp", "1", "--lang", "en", "03-ray-casting"] + bundle())
    if os.listdir(top) != ["site"]:
        fail("left beside the site after the next export: %s" % os.listdir(top))
    if intact() or not os.path.exists(os.path.join(out, "lessons", "03-ray-casting.js")):
        fail("the next export did not replace the site")
    print("Ctrl-C: old site intact; the next export leaves nothing beside it")


def check_fulldisk():
    top = os.path.join(WORK, "web-fulldisk")
    os.makedirs(top, exist_ok=True)
    subprocess.run(["umount", top], capture_output=True)
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", top],
                      capture_output=True).returncode != 0:
        print("SKIP: cannot mount a 1 MB tmpfs (needs root)")
        sys.exit(77)
    try:
        out = os.path.join(top, "site")
        intact = old_site(out)
        result = run(["web", "--out", out, "--max-spp", "1", "--lang", "en", "04-whitted"] +
                     bundle(), code=1)
        if not re.search(r"raylab: error: .*(No space left on device|cannot be written)",
                         result.stderr):
            fail("the message does not say the disk is full: " + result.stderr)
        if not intact():
            fail("the old site changed")
        if os.listdir(top) != ["site"]:
            fail("left beside the site: %s" % os.listdir(top))
        print("full disk: old site intact: " + result.stderr.strip())
    finally:
        subprocess.run(["umount", top], capture_output=True)


{"rays": check_rays, "course": check_course, "interrupt": check_interrupt, "fulldisk": check_fulldisk, "hostile": check_hostile, "survive": check_survive,
 "student": check_student, "bounded": check_bounded}[CHECK]()
