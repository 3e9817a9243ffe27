"""What stepping from Python costs (docs/performance.md, "Python"), in one run so that the ratios
are fair on a shared machine:

1. The settled 20k bed (bench/scenes/settled_bed_20k.toml, 5,000 steps) through `veridem run` and
   through the module's sim.step(100), alternately, ROUNDS times on 1 and on 2 threads: the
   particle-steps per second of each and their ratio per round (Python / veridem run).
2. The cost of a call: one ball in free flight (a step of ~0.1 us), N calls of sim.step(1)
   against one sim.step(N): (T_calls - T_one) / N is what a call adds to its step.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_overhead.py [BUILD_DIR] [ROUNDS]
"""
import os
import re
import subprocess
import sys
import tempfile
import time

import veridem

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "..", "build", "release")
ROUNDS = int(sys.argv[2]) if len(sys.argv) > 2 else 3
SCENE = os.path.join(HERE, "scenes", "settled_bed_20k.toml")


def cli_rate(threads, out):
    done = subprocess.run([os.path.join(BUILD, "src", "app", "veridem"), "run", SCENE, "--quiet", "--out", out,
                           "--threads", str(threads)], capture_output=True, text=True, check=True)
    return float(re.search(r"([0-9.e+]+) particle-steps/s", done.stdout).group(1))


def python_rate(threads, out):
    veridem.set_threads(threads)
    sim = veridem.Simulation(SCENE, out=out, quiet=True)
    n = len(sim.particles)
    start = time.perf_counter()
    while sim.step_count < sim.end_step:
        sim.step(100)
    seconds = time.perf_counter() - start
    sim.close()
    return n * sim.end_step / seconds


def call_overhead(calls=100000):
    scene = {"simulation": {"dt": 1e-5, "duration": 10.0, "output_interval": 10.0, "gravity": [0, 0, -9.81]},
             "material": [{"name": "m", "density": 1000, "kn": 1e3}],
             "sphere": [{"material": "m", "radius": 0.01, "position": [0, 0, 100.0]}]}
    a = veridem.Simulation(scene, quiet=True)
    start = time.perf_counter()
    for _ in range(calls):
        a.step(1)
    t_calls = time.perf_counter() - start
    b = veridem.Simulation(scene, quiet=True)
    start = time.perf_counter()
    b.step(calls)
    t_one = time.perf_counter() - start
    return t_calls, t_one, (t_calls - t_one) / calls


def main():
    print(f"veridem {veridem.__version__}; {os.cpu_count()} CPUs; {time.strftime('%Y-%m-%d %H:%M:%S')}")
    with tempfile.TemporaryDirectory() as tmp:
        for threads in (1, 2):
            for r in range(ROUNDS):
                cli = cli_rate(threads, os.path.join(tmp, "cli"))
                py = python_rate(threads, os.path.join(tmp, "py"))
                print(f"bed 20k, {threads} thread(s), round {r + 1}: veridem run {cli:.4g}, Python step(100) "
                      f"{py:.4g} particle-steps/s, ratio {py / cli:.3f}")
    veridem.set_threads(1)
    t_calls, t_one, per_call = call_overhead()
    print(f"one ball, 100000 x step(1): {t_calls:.3f} s; step(100000): {t_one:.3f} s; "
          f"per call {1e6 * per_call:.2f} us above the step")


if __name__ == "__main__":
    main()
