"""A signal is honoured within one second wherever the run is (docs/scene-format.md, "Checkpoint
and restart"): SIGTERM sent while a run writes an output (signal_output.toml: every step is
written; the signal goes when a .vtp.tmp file exists, i.e. in the middle of a frame) and while it
rebuilds its contact lists at every step (signal_rebuild.toml, skin 1 nm; the signal goes at a
random moment after stepping started, when most of the time is rebuilding) must end the run with
a checkpoint, "stopped by SIGTERM" and exit status 143 within 1 s of the signal.

usage: /usr/bin/python3 signal_check.py VERIDEM OUTPUT_SCENE REBUILD_SCENE OUT_DIR
"""
import glob
import os
import random
import shutil
import signal
import subprocess
import sys
import time

veridem, output_scene, rebuild_scene, out = sys.argv[1:5]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
failures = []
LIMIT = 1.0  # [s] from the signal to the exit


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message)


def stepping(directory):
    """The run is in its step loop: thermo.csv has a row after t = 0."""
    thermo = f"{directory}/thermo.csv"
    return os.path.exists(thermo) and len(open(thermo).read().splitlines()) >= 3


def stop(scene, name, ready):
    directory = f"{out}/{name}"
    process = subprocess.Popen([veridem, "run", scene, "--quiet", "--threads", "1", "--out", directory],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 120
    while time.time() < deadline and process.poll() is None and not ready(directory):
        time.sleep(0.0005)
    sent = time.monotonic()
    process.send_signal(signal.SIGTERM)
    _, stderr = process.communicate()
    elapsed = time.monotonic() - sent
    print(f"{name}: exit {process.returncode} {elapsed:.3f} s after SIGTERM")
    check(process.returncode == 143, f"{name}: exit {process.returncode}, expected 143: {stderr.strip()}")
    check("stopped by SIGTERM" in stderr, f"{name}: no 'stopped by SIGTERM': {stderr.strip()}")
    check(os.path.exists(f"{directory}/checkpoint.bin"), f"{name}: no checkpoint")
    check(elapsed < LIMIT, f"{name}: {elapsed:.3f} s from the signal to the exit (limit {LIMIT} s)")


# During an output: wait for a frame being written (its .tmp file), after the first steps.
stop(output_scene, "during_output",
     lambda d: stepping(d) and glob.glob(f"{d}/particles_*.vtp.tmp"))
# During the rebuilds: a random moment 0-0.5 s after stepping started.
delay = random.uniform(0, 0.5)
started = []


def rebuilding(d):
    if not started and stepping(d):
        started.append(time.monotonic())
    return started and time.monotonic() - started[0] > delay


stop(rebuild_scene, "during_rebuilds", rebuilding)

if failures:
    raise SystemExit(f"signal: {len(failures)} failure(s)")
print("signal: OK")
