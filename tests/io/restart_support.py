"""What the restart checks (restart_check.py, restart_flow_check.py, restart_mesh_check.py) share:
running veridem, reading a checkpoint's records, comparing states and output files, and
collecting failures."""
import os
import shutil
import struct
import subprocess


class RestartCheck:
    """Runs `veridem` into directories under `out` (emptied first) and collects failures."""

    def __init__(self, veridem, out):
        self.veridem, self.out, self.failures = veridem, out, []
        shutil.rmtree(out, ignore_errors=True)
        os.makedirs(out)

    def check(self, condition, message):
        if not condition:
            self.failures.append(message)
            print("FAIL:", message)

    def run(self, scene, directory, *extra, expect=0):
        command = [self.veridem, "run", scene, "--quiet", "--out", f"{self.out}/{directory}", *extra]
        result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.check(result.returncode == expect,
                   f"{' '.join(command)}: exit {result.returncode}, expected {expect}: {result.stderr.strip()}")
        return result

    def same_state(self, a, b, what):
        """Checkpoints a and b hold the same records (all but the output files' sizes)."""
        ra, rb = records(a), records(b)
        differ = [t for t in ra if t not in ("csvB",) and ra[t] != rb.get(t)]
        self.check(not differ and ra.keys() == rb.keys(), f"{what}: records differ: {differ}")

    def same_files(self, a, b, names, what):
        """The files `names` of run directories a and b are byte-identical."""
        for name in names:
            self.check(open(f"{self.out}/{a}/{name}", "rb").read() == open(f"{self.out}/{b}/{name}", "rb").read(),
                       f"{what}: {name} differs")

    def stop_and_restart(self, scene, stops, names):
        """For each step in `stops`: a run of `scene` on 1 thread stopped there with a checkpoint,
        continued on 2 threads, must end in the straight run's state (its directory "straight",
        run before) and write the same files `names`, byte for byte."""
        for stop in stops:
            split = f"split{stop}"
            self.run(scene, split, "--threads", "1", "--stop-at-step", str(stop))
            self.run(scene, split, "--threads", "2", "--restart", f"{self.out}/{split}/checkpoint.bin")
            self.same_state(f"{self.out}/straight/checkpoint.bin", f"{self.out}/{split}/checkpoint.bin",
                            f"stopped at {stop}")
            self.same_files("straight", split, names, f"stopped at {stop}")

    def finish(self, what):
        print(f"{what}: " + ("OK" if not self.failures else f"{len(self.failures)} failure(s)"))
        return 1 if self.failures else 0


def records(path):
    """The checkpoint's records, {tag: bytes}, after checking the container's framing."""
    data = open(path, "rb").read()
    assert data[:8] == b"VDMCKPT\0", path
    payload = struct.unpack_from("<Q", data, len(data) - 24)[0]
    assert payload == len(data) - 32 - 24 and data[-8:] == b"VDMCKEND", path
    result, k = {}, 32
    while k < len(data) - 24:
        tag = data[k:k + 4].decode()
        size, count = struct.unpack_from("<IQ", data, k + 4)
        result[tag] = data[k + 16:k + 16 + size * count]
        k += 16 + size * count
    return result


def nonzero_doubles(blob):
    return sum(1 for (v,) in struct.iter_unpack("<d", blob) if v != 0)
