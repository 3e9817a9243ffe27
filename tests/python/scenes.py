"""Small scenes for the Python tests, built as dicts in the TOML vocabulary (docs/scene-format.md)."""


def box_fill(duration=0.02, output_interval=0.01, energy=False):
    """Glass beads falling into an open box: 5 plane walls, a lattice of 252 spheres; the same
    scene as tests/python/box_fill.toml (the TOML twin)."""
    walls = [
        {"name": "floor", "material": "glass", "normal": [0, 0, 1]},
        {"name": "west", "material": "glass", "point": [0, 0, 0], "normal": [1, 0, 0]},
        {"name": "east", "material": "glass", "point": [0.03, 0, 0], "normal": [-1, 0, 0]},
        {"name": "south", "material": "glass", "point": [0, 0, 0], "normal": [0, 1, 0]},
        {"name": "north", "material": "glass", "point": [0, 0.03, 0], "normal": [0, -1, 0]},
    ]
    scene = {
        "simulation": {"dt": 2e-5, "duration": duration, "output_interval": output_interval,
                       "gravity": [0, 0, -9.81], "skin": 3e-4},
        "material": [{"name": "glass", "density": 2500, "kn": 500, "restitution": 0.5, "friction": 0.4}],
        "wall": walls,
        "lattice": [{"material": "glass", "radius": 1.5e-3, "min": [0.002, 0.002, 0.004],
                     "max": [0.028, 0.028, 0.02], "spacing": 3.6e-3, "jitter": 1e-4,
                     "velocity": [0, 0, -0.2]}],
    }
    if energy:
        scene["output"] = {"energy": True}
    return scene


SIDE = 0.0194  # m: the oedometer's box, 8 spheres of radius 1.2 mm across with 0.02 mm between


def oedometer(duration=0.15):
    """A box of spheres without gravity, closed by a lid ('lid', a plane facing down) that a
    servo moves (test_servo): 8 x 8 x 6 spheres of radius 1.2 mm on a cubic lattice 0.02 mm apart
    (columns that carry the lid's load as soon as it touches)."""
    walls = [
        {"name": "floor", "material": "grain", "normal": [0, 0, 1]},
        {"name": "west", "material": "grain", "point": [0, 0, 0], "normal": [1, 0, 0]},
        {"name": "east", "material": "grain", "point": [SIDE, 0, 0], "normal": [-1, 0, 0]},
        {"name": "south", "material": "grain", "point": [0, 0, 0], "normal": [0, 1, 0]},
        {"name": "north", "material": "grain", "point": [0, SIDE, 0], "normal": [0, -1, 0]},
        {"name": "lid", "material": "grain", "point": [0, 0, 0.0146], "normal": [0, 0, -1]},
    ]
    return {
        "simulation": {"dt": 1e-5, "duration": duration, "output_interval": duration, "gravity": [0, 0, 0],
                       "skin": 2e-4},
        "material": [{"name": "grain", "density": 2500, "kn": 2e3, "restitution": 0.3, "friction": 0.3}],
        "wall": walls,
        "lattice": [{"material": "grain", "radius": 1.2e-3, "min": [0, 0, 0], "max": [SIDE, SIDE, 0.0146],
                     "spacing": 2.42e-3, "jitter": 1e-5}],
    }


def pour(duration=0.05):
    """Spheres poured into a box by an inserter and taken out by an outlet: the particle arrays
    move while it runs."""
    scene = box_fill(duration=duration)
    del scene["lattice"]
    scene["insert"] = [{"material": "glass", "radius": 1e-3, "min": [0.005, 0.005, 0.02],
                        "max": [0.025, 0.025, 0.03], "rate": 20000, "velocity": [0, 0, -0.5]}]
    scene["outlet"] = [{"type": "box", "min": [0.0, 0.0, 0.0], "max": [0.03, 0.03, 0.004]}]
    return scene
