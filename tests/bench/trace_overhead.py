#!/usr/bin/env python3
"""The cost of tracing one pixel sample from Python against the same trace in C++.

    PYTHONPATH=build/release/python python3 tests/bench/trace_overhead.py \
        [--bench build/release/tests/bench/raylab_bench_trace] [--repeat 2000]

For each algorithm: raylab.trace(scene, (200, 150), sample) on the built-in scene (what
the C++ benchmark TracePixel/A times with tracePixel), best of 5 runs of `--repeat` calls;
then the same with the tree turned into Python (arrays(), and every segment's to_dict()).
With --bench, runs the C++ benchmark and prints the overhead per call and as a ratio.
Not a test: timings depend on the machine and what else it runs.
"""

import argparse
import json
import subprocess
import time

import raylab


def per_call(function, repeat):
    best = float("inf")
    for _ in range(5):
        start = time.perf_counter()
        for i in range(repeat):
            function(i)
        best = min(best, (time.perf_counter() - start) / repeat)
    return best


def cpp_times(bench):
    done = subprocess.run([bench, "--benchmark_format=json", "--benchmark_min_time=0.5",
                           "--benchmark_repetitions=3", "--benchmark_report_aggregates_only=true"],
                          capture_output=True, text=True, check=True)
    times = {}
    for case in json.loads(done.stdout)["benchmarks"]:
        if case.get("aggregate_name") == "median":
            times[case["label"]] = case["real_time"] * 1e-6  # microseconds
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bench", help="the raylab_bench_trace program (C++ figures)")
    parser.add_argument("--repeat", type=int, default=2000)
    args = parser.parse_args()

    scene = raylab.default_scene()
    cpp = cpp_times(args.bench) if args.bench else {}
    print(f"{'algorithm':12s} {'rays':>5s} {'python us':>10s} {'c++ us':>8s} {'overhead us':>12s}"
          f" {'ratio':>6s} {'+ to Python us':>15s}")
    for algorithm in raylab.ALGORITHMS:
        rays = len(raylab.trace(scene, (200, 150), algorithm=algorithm))
        python = per_call(lambda i: raylab.trace(scene, (200, 150), i % 64, algorithm=algorithm),
                          args.repeat)

        def with_tree(i):
            trace = raylab.trace(scene, (200, 150), i % 64, algorithm=algorithm)
            trace.arrays()
            [s.to_dict() for s in trace.segments]

        converted = per_call(with_tree, max(1, args.repeat // 4))
        line = f"{algorithm:12s} {rays:5d} {python * 1e6:10.1f}"
        if algorithm in cpp:
            c = cpp[algorithm]
            line += f" {c * 1e6:8.1f} {(python - c) * 1e6:12.1f} {python / c:6.2f}"
        else:
            line += f" {'':8s} {'':12s} {'':6s}"
        print(line + f" {converted * 1e6:15.1f}")


if __name__ == "__main__":
    main()
