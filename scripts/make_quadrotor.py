#!/usr/bin/env python3
"""Writes examples/bodies/quadrotor.obj and quadrotor_props.obj: a quadrotor-like body in metres.

The body: a 10 cm flight-controller board (1.6 mm thick) on a battery box, four arms along the
diagonals to motor pods 17 cm from the centre, and a propeller disc (13 cm across, zero
thickness) above each pod. Like a real drone's mesh it is open (the pods have no bottom, the
discs are single sheets) and not manifold (arms pass through the board and the pods). z is up:
a camera above the drone looks down -z. The props file is the keep-out volume of the spinning
propellers (a closed cylinder around each disc) for `vantage place --exclude`.

Deterministic: run it again and the files are byte-identical.
    python3 scripts/make_quadrotor.py [OUT_DIR]   (default examples/bodies)
"""

import math
import pathlib
import sys

ARM_RADIUS = 0.17  # motor axis distance from the centre
POD_RADIUS = 0.014
PROP_RADIUS = 0.065
PROP_HEIGHT = 0.035
SIDES = 24


class Mesh:
    def __init__(self, header):
        self.lines = [f"# {line}" for line in header]
        self.count = 0

    def part(self, name, vertices, faces):
        """Adds a named part: vertices (x, y, z), faces as 0-based indices into them."""
        self.lines.append(f"o {name}")
        for v in vertices:
            self.lines.append("v " + " ".join(f"{c:.6f}" for c in v))
        for f in faces:
            self.lines.append("f " + " ".join(str(self.count + i + 1) for i in f))
        self.count += len(vertices)

    def write(self, path):
        path.write_text("\n".join(self.lines) + "\n")


def box(cx, cy, z0, z1, half_length, half_width, angle):
    """A closed box along direction angle (radians), outward-wound quads."""
    c, s = math.cos(angle), math.sin(angle)
    corners = []
    for u, w in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
        x = cx + u * half_length * c - w * half_width * s
        y = cy + u * half_length * s + w * half_width * c
        corners.append((x, y))
    vertices = [(x, y, z0) for x, y in corners] + [(x, y, z1) for x, y in corners]
    faces = [(3, 2, 1, 0), (4, 5, 6, 7)]
    for i in range(4):
        j = (i + 1) % 4
        faces.append((i, j, j + 4, i + 4))
    return vertices, faces


def cylinder(cx, cy, z0, z1, radius, bottom):
    """A cylinder of SIDES sides with a top cap, and a bottom cap only when bottom is true."""
    ring = [(cx + radius * math.cos(2 * math.pi * k / SIDES),
             cy + radius * math.sin(2 * math.pi * k / SIDES)) for k in range(SIDES)]
    vertices = [(x, y, z0) for x, y in ring] + [(x, y, z1) for x, y in ring]
    faces = [tuple(SIDES + k for k in range(SIDES))]
    if bottom:
        faces.append(tuple(reversed(range(SIDES))))
    for k in range(SIDES):
        j = (k + 1) % SIDES
        faces.append((k, j, SIDES + j, SIDES + k))
    return vertices, faces


def disc(cx, cy, z, radius):
    """A single-sided disc facing +z (a fan around its centre)."""
    vertices = [(cx, cy, z)] + [(cx + radius * math.cos(2 * math.pi * k / SIDES),
                                 cy + radius * math.sin(2 * math.pi * k / SIDES), z)
                                for k in range(SIDES)]
    faces = [(0, 1 + k, 1 + (k + 1) % SIDES) for k in range(SIDES)]
    return vertices, faces


def motor_centres():
    return [(ARM_RADIUS * math.cos(a), ARM_RADIUS * math.sin(a), a)
            for a in (math.pi / 4, 3 * math.pi / 4, 5 * math.pi / 4, 7 * math.pi / 4)]


def main():
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "examples/bodies")
    body = Mesh(["quadrotor (metres, z up): written by scripts/make_quadrotor.py",
                 "a 10 cm board on a battery, four arms, motor pods and propeller discs;",
                 "open (pods without bottoms, single-sided discs) and not manifold"])
    body.part("board", *box(0, 0, 0.0, 0.0016, 0.05, 0.05, 0.0))
    body.part("battery", *box(0, 0, -0.03, 0.0, 0.035, 0.02, 0.0))
    for i, (x, y, a) in enumerate(motor_centres()):
        r = 0.5 * (0.03 + ARM_RADIUS)
        body.part(f"arm{i}", *box(r * math.cos(a), r * math.sin(a), -0.006, 0.004,
                                  0.5 * (ARM_RADIUS - 0.03), 0.006, a))
        body.part(f"pod{i}", *cylinder(x, y, -0.006, 0.03, POD_RADIUS, bottom=False))
        body.part(f"prop{i}", *disc(x, y, PROP_HEIGHT, PROP_RADIUS))
    body.write(out / "quadrotor.obj")

    props = Mesh(["quadrotor_props (metres): the keep-out volumes of quadrotor.obj's spinning",
                  "propellers, written by scripts/make_quadrotor.py"])
    for i, (x, y, _) in enumerate(motor_centres()):
        props.part(f"prop{i}_sweep", *cylinder(x, y, PROP_HEIGHT - 0.005, PROP_HEIGHT + 0.005,
                                                PROP_RADIUS + 0.005, bottom=True))
    props.write(out / "quadrotor_props.obj")


if __name__ == "__main__":
    main()
