"""veridem: verified DEM contact physics, driven from Python.

    import veridem
    sim = veridem.Simulation("examples/hopper_discharge.toml", out="out/hopper")
    sim.run(until=0.5, every=1000, callback=lambda s: print(s.time, len(s.contacts()["i"])))
    x = sim.particles.position          # (N, 3) numpy view of the engine's own memory [m]

SI units throughout (m, s, kg, N, N m, rad/s, Pa, J). The scene vocabulary is the TOML scene
format's (docs/scene-format.md); the reference is docs/python.md.
"""

import json
import os
import subprocess
import tempfile

from ._veridem import SimulationError, _Simulation, set_threads, threads
from ._build import VERIDEM_EXECUTABLE, VERSION

__all__ = ["Simulation", "SimulationError", "Particles", "verify", "set_threads", "threads", "__version__"]
__version__ = VERSION


def _positive_int(value, name):
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"{name}: expected an int (got {type(value).__name__})")
    if value < 0:
        raise ValueError(f"{name}: expected an int >= 0 (got {value})")
    return value


def _finite_number(value, name):
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"{name}: expected a number (got {type(value).__name__})")
    value = float(value)
    if value != value or value in (float("inf"), float("-inf")):
        raise ValueError(f"{name}: expected a finite number (got {value})")
    return value


class Particles:
    """Zero-copy numpy views of the particle arrays, one row per particle in the engine's slot
    order (`id` gives each row's stable particle id). Each attribute access returns a fresh view
    of the current arrays; a view kept across a call that may move the arrays (a step of a scene
    with inserters or outlets, add_particle, remove_particles, restore) becomes a read-only
    snapshot of the state before that call (docs/python.md, "Views").

    Read-only: position [m], force [N] (contact sums plus external force, gravity excluded),
    torque [N m], radius [m], mass [kg], material (index into Simulation.materials), id.
    Writable: velocity [m/s], angular_velocity [rad/s], external_force [N], external_torque [N m]
    (added to the contact sums every step until changed; not checkpointed)."""

    _names = ("position", "velocity", "angular_velocity", "force", "torque", "radius", "mass",
              "material", "id", "external_force", "external_torque")

    def __init__(self, sim):
        self._sim = sim

    def __getattr__(self, name):
        if name in Particles._names:
            return self._sim.view(name)
        raise AttributeError(f"no particle array is named '{name}' (one of: {', '.join(Particles._names)})")

    def __len__(self):
        return self._sim.particle_count


class Simulation:
    """A DEM scene: from a TOML file (a path) or a dict in the TOML vocabulary.

    out: output directory for the scene's files (None: no files; checkpoints still can be
    written to a given path). quiet: no start-up notes. force_dt: run above the stability limit.
    restart: continue from a checkpoint of this scene (the same bits as the run that wrote it).
    name: what a dict scene is called in messages (and the base of its relative paths)."""

    def __init__(self, scene, out=None, *, quiet=False, force_dt=False, restart=None, name=None):
        restart = "" if restart is None else os.fspath(restart)
        out = None if out is None else os.fspath(out)
        if isinstance(scene, dict):
            self._sim = _Simulation.from_dict(scene, name or "<dict scene>", out, bool(quiet), bool(force_dt),
                                              restart)
        elif isinstance(scene, (str, os.PathLike)):
            self._sim = _Simulation.from_file(os.fspath(scene), out, bool(quiet), bool(force_dt), restart)
        else:
            raise TypeError(f"scene: expected a file path or a dict (got {type(scene).__name__})")
        self.particles = Particles(self._sim)

    # --- time -----------------------------------------------------------------------------
    @property
    def dt(self):
        """The time step [s]."""
        return self._sim.dt

    @property
    def time(self):
        """Simulated time [s] (step_count * dt as the step accumulates it)."""
        return self._sim.time

    @property
    def step_count(self):
        """Steps taken since the scene's start."""
        return self._sim.step_count

    @property
    def end_step(self):
        """The scene's duration in steps ([simulation] duration / dt)."""
        return self._sim.end_step

    def step(self, n=1):
        """Runs n steps (not past the scene's duration), with the scene's outputs, checkpoints and
        particle flow at their times. The GIL is released; Ctrl-C raises KeyboardInterrupt
        within ~50 ms. Returns the steps taken."""
        return self._sim.step(_positive_int(n, "n"))

    def run(self, until=None, *, steps=None, every=None, callback=None):
        """Steps to time `until` [s] (rounded to the nearest step) or for `steps` steps (default:
        to the end of the scene), calling callback(sim) every `every` steps (counted from the
        scene's start). An exception in the callback stops the run and propagates with its
        traceback; the outputs written so far are kept. Returns the steps taken."""
        if until is not None and steps is not None:
            raise ValueError("run: give `until` or `steps`, not both")
        if until is not None:
            end = round(_finite_number(until, "until") / self.dt)
            if end < self.step_count:
                raise ValueError(f"until: {until} s is before the current time {self.time} s")
        elif steps is not None:
            end = self.step_count + _positive_int(steps, "steps")
        else:
            end = self.end_step
        end = min(end, self.end_step)
        if callback is not None and not callable(callback):
            raise TypeError("callback: expected a callable taking the simulation")
        if every is not None:
            every = _positive_int(every, "every")
            if every == 0:
                raise ValueError("every: expected an int >= 1")
        elif callback is not None:
            raise ValueError("run: a callback needs `every` (steps between calls)")
        first = self.step_count
        while self.step_count < end:
            target = end
            if every:
                target = min(end, (self.step_count // every + 1) * every)
            if self._sim.step(target - self.step_count) == 0:
                break
            if callback is not None and self.step_count % every == 0:
                callback(self)
        return self.step_count - first

    # --- walls ----------------------------------------------------------------------------
    @property
    def walls(self):
        """The walls' names, in scene order."""
        return self._sim.wall_names()

    @property
    def materials(self):
        """The materials' names; Particles.material indexes this list."""
        return self._sim.material_names()

    def set_wall_velocity(self, wall, velocity):
        """The named wall's translation velocity [m/s] from the next step on."""
        self._sim.set_wall_velocity(wall, velocity)

    def set_wall_angular_velocity(self, wall, angular_velocity):
        """The named wall's angular velocity [rad/s] (an analytic wall about its symmetry axis)."""
        self._sim.set_wall_angular_velocity(wall, angular_velocity)

    def wall_displacement(self, wall):
        """The named wall's translation since t = 0 [m], as (x, y, z)."""
        return self._sim.wall_displacement(wall)

    def wall_load(self, wall):
        """(force [N], torque [N m]) of the particles on the named wall in the last step."""
        return self._sim.wall_load(wall)

    # --- particles and contacts -----------------------------------------------------------
    def add_particle(self, material, radius, position, velocity=(0, 0, 0), angular_velocity=(0, 0, 0)):
        """Adds a sphere of the named material, radius [m] at position [m]; returns its id."""
        return self._sim.add_particle(material, _finite_number(radius, "radius"), position, velocity,
                                      angular_velocity)

    def remove_particles(self, ids):
        """Removes the particles with these ids (an unknown id: ValueError, nothing removed)."""
        return self._sim.remove_particles([_positive_int(int(i), "ids") for i in ids])

    def contacts(self):
        """Every touching contact now, as a dict of arrays: i, j (particle ids; j = -1 for a wall),
        wall (index into `walls`, -1 for a pair), overlap [m], normal (unit, partner to i),
        point [m], normal_force and tangential_force on i [N]; plus wall_names."""
        c = self._sim.contacts()
        c["wall_names"] = self.walls
        return c

    def energies(self):
        """Kinetic energies [J]; with [output] energy = true, the energy ledger's terms too."""
        return self._sim.energies()

    # --- checkpoints and files ------------------------------------------------------------
    def checkpoint(self, path=None):
        """Writes a checkpoint (default: OUT/checkpoint.bin) from which Simulation(...,
        restart=path) or restore() continues with the same bits."""
        self._sim.checkpoint(None if path is None else os.fspath(path))

    @property
    def checkpoint_is_current(self):
        """True if OUT/checkpoint.bin holds the present step (written by the scene's schedule or by
        checkpoint() at this step, no restore() since)."""
        return self._sim.checkpoint_is_current

    def restore(self, path):
        """Returns this scene to a checkpoint's state (written by the same scene)."""
        self._sim.restore(os.fspath(path))

    def close(self):
        """Flushes and closes the output files (also done when the object goes away)."""
        self._sim.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False


def verify(labels=None, cases=None, jobs=None):
    """Runs verification cases with `veridem verify` and returns its JSON results (the same dict
    as `veridem verify --json`). labels, cases: lists of names (default: the quick label)."""
    args = [VERIDEM_EXECUTABLE, "verify", "--quiet"]
    if not labels and not cases:
        labels = ["quick"]
    for label in labels or []:
        args += ["--label", str(label)]
    for case in cases or []:
        args += ["--case", str(case)]
    if jobs is not None:
        args += ["--jobs", str(_positive_int(jobs, "jobs"))]
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "results.json")
        done = subprocess.run(args + ["--json", path], capture_output=True, text=True)
        if not os.path.exists(path):
            raise SimulationError(f"veridem verify failed (status {done.returncode}): {done.stderr.strip()}")
        with open(path) as f:
            return json.load(f)
