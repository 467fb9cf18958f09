"""Writes a Whitted tree of the default scene as another tracer with a bug would: RayLab's own
dump (raylab trace --json) with the first refraction ray bent (the test app.DiffBentRefraction).

    python3 BendRay.py WITH_DISPLAY RAYLAB OUT.json
"""
import json
import math
import subprocess
import sys

with_display, raylab, out = sys.argv[1:4]
subprocess.run([with_display, raylab, "trace", "--algorithm", "whitted", "--pixel", "90", "100",
                "--size", "64x48", "--out", out[:-5] + "_trace.png", "--json", out],
               check=True, stdout=subprocess.DEVNULL)
with open(out) as f:
    tree = json.load(f)
ray = next(s for s in tree["segments"] if s["kind"] == "refraction")
d = [ray["direction"][0] + 0.3, ray["direction"][1], ray["direction"][2]]
n = math.sqrt(sum(x * x for x in d))
ray["direction"] = [x / n for x in d]
length = math.dist(ray["origin"], ray["end_point"])
ray["end_point"] = [o + length * x for o, x in zip(ray["origin"], ray["direction"])]
with open(out, "w") as f:
    json.dump(tree, f)
print(ray["id"])
