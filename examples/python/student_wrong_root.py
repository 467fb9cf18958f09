"""A student's ray-sphere test that takes the far root, traced by raylab.student: the
student's tree coloured by verdict beside the engine's (README's "Checking your own code"
picture). Needs an X server: xvfb-run -a python3 examples/python/student_wrong_root.py OUT.png
"""

import math
import sys

import numpy as np

import raylab
import raylab.student as student


def intersect_sphere(origin, direction, center, radius, t_min, t_max):
    oc = origin - center
    b = np.dot(oc, direction)
    disc = b * b - (np.dot(oc, oc) - radius * radius)
    if disc < 0:
        return None
    t = -b + math.sqrt(disc)  # the bug: always the far root
    return t if t_min <= t <= t_max else None


scene = raylab.default_scene()
student.use(intersect_sphere=intersect_sphere)
trace = student.trace(scene, (84, 90), algorithm="path", spp=1)
print("verdicts:", trace.verdicts, "first divergent ray:", trace.first_divergent)
call = trace.calls[trace.deciding_calls[trace.first_divergent]]
print("student t = %r, exact t = %r (%s)" % (call["student"], call["reference"], call["verdict"]))
student.save_view(sys.argv[1] if len(sys.argv) > 1 else "student_wrong_root.png", scene, trace,
                  width=480, height=360)
