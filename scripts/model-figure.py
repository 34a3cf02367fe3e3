#!/usr/bin/env python3
"""Draws the labelled model figures of docs/scene-language.md:
docs/model-robot.png (the robot F-2 from the front and from the side, arms
swung by rx) and docs/model-human.png (the human from the front).

Usage: scripts/model-figure.py [path/to/f2]   (default build/release/apps/cli/f2)
Needs ImageMagick's `convert`. Label places are model coordinates projected
with the camera formula of SPEC 2, so the leader lines end on the parts.
"""
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
F2 = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build/release/apps/cli/f2")
FONT = "DejaVu-Sans"

# Part colours, the same in every view.
COLOURS = {"body": "120 160 220", "head": "235 200 90", "lhand": "225 110 110", "rhand": "120 200 120"}

# The model's root stands at depth DEPTH; the camera makes one scene unit
# SCALE pixels at that depth. TOP is a band above the render for the title.
DEPTH = 400
SCALE = 2.0
HEIGHT = 520
EYE_Y = -5
TOP = 64


class Panel:
    """One rendered view of one model, with its labels."""

    def __init__(self, width, mirror):
        self.width = width
        self.mirror = mirror  # the model faces the camera (ry 180): local +x is the image's left
        self.draw = []

    def pixel(self, x, y):
        """Pixel of the model-local point (x, y, 0) (the root at the centre of the view)."""
        if self.mirror:
            x = -x
        return self.width / 2 + SCALE * x, TOP + HEIGHT / 2 - SCALE * (y - EYE_Y)

    def pivot(self, x, y):
        px, py = self.pixel(x, y)
        self.draw += ["-fill", "white", "-stroke", "black", "-strokewidth", "1.5",
                      "-draw", f"circle {px:.0f},{py:.0f} {px + 4:.0f},{py:.0f}"]

    def label(self, at, text, column, row):
        """Text in the left (column < 0) or right column at height `row` (both
        in scene units from the root), with a leader line to the model point `at`."""
        px, py = self.pixel(*at)
        tx = self.width / 2 + SCALE * column
        ty = TOP + HEIGHT / 2 - SCALE * (row - EYE_Y)
        self.draw += ["-stroke", "gray35", "-strokewidth", "1",
                      "-draw", f"line {px:.0f},{py:.0f} {tx:.0f},{ty:.0f}", "-stroke", "none", "-fill", "black"]
        if column < 0:
            self.draw += ["-gravity", "NorthEast", "-annotate", f"+{self.width - tx + 4:.0f}+{ty - 8:.0f}", text]
        else:
            self.draw += ["-gravity", "NorthWest", "-annotate", f"+{tx + 4:.0f}+{ty - 8:.0f}", text]

    def title(self, text):
        self.draw += ["-stroke", "none", "-fill", "black", "-gravity", "North", "-pointsize", "14",
                      "-annotate", "+0+8", text, "-pointsize", "12"]

    def render(self, commands, tmp, name):
        d = SCALE * DEPTH / self.width  # screen distance: SCALE pixels per unit at DEPTH
        text = "\n".join([f"/camera {self.width} {HEIGHT} {d:.6f} 0 {EYE_Y} 0", "/background 250 250 250",
                          "/amb_light 0.45", "/dir_light 0.7 0.4 -0.5 1"] + commands) + "\n"
        scene = pathlib.Path(tmp) / f"{name}.f2"
        scene.write_text(text)
        raw = pathlib.Path(tmp) / f"{name}_raw.png"
        subprocess.run([F2, "render", str(scene), "-o", str(raw), "--aa", "3"], check=True,
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        out = pathlib.Path(tmp) / f"{name}.png"
        subprocess.run(["convert", str(raw), "-background", "rgb(250,250,250)", "-gravity", "North",
                        "-splice", f"0x{TOP}", "-font", FONT, "-pointsize", "12"] + self.draw + [str(out)],
                       check=True)
        return out


def paint(name):
    return [f"/paint {name}.{part} {rgb}" for part, rgb in COLOURS.items()]


def robot_front(tmp):
    p = Panel(840, mirror=True)
    for at in [(0, 0), (0, -105), (0, 45), (52, 35), (-52, 35)]:
        p.pivot(*at)
    p.label((20, 70), "head: box 60 × 50 × 50\ncentre (0 25 0), pivot (0 150 0)", -90, 112)
    p.label((52, 10), "rhand: cylinder r 10, h 100\ncentre (0 -50 0), pivot (52 140 0)", -90, 20)
    p.label((0, 0), "root: the /robot position", -90, -35)
    p.label((0, -105), "body pivot (0 -105 0) in root:\nthe feet", -90, -95)
    p.label((-14, 80), "eyes: spheres r 6, colour 20 20 20,\ncentres (±14 30 25) in head", 90, 112)
    p.label((-52, 10), "lhand: cylinder r 10, h 100\ncentre (0 -50 0), pivot (-52 140 0)", 90, 20)
    p.label((-20, -60), "body: cylinder r 40, h 150\ncentre (0 75 0)", 90, -80)
    p.title("Robot F-2 from the front (turned to face the camera: its right hand is on the image's left)\n"
            "white dots: pivots; sizes in scene units (cm); positions in the parent's frame")
    return p.render([f"/robot r 0 0 {DEPTH} 0 180 0"] + paint("r"), tmp, "robot_front")


def robot_side(tmp):
    p = Panel(560, mirror=False)  # ry 90 turns local +z to the image's right: it faces right
    p.pivot(0, 35)
    p.label((-60, 0), "rhand  rx = +60\nbackward-up", -85, 100)
    p.label((65, -2), "lhand  rx = −60\nforward-up", 85, 100)
    arrow_y = TOP + HEIGHT / 2 - SCALE * (-80 - EYE_Y)
    x0, x1 = p.width / 2 + SCALE * 45, p.width / 2 + SCALE * 100
    p.draw += ["-stroke", "black", "-strokewidth", "2", "-draw", f"line {x0:.0f},{arrow_y:.0f} {x1:.0f},{arrow_y:.0f}",
               "-fill", "black", "-draw",
               f"polygon {x1 + 8:.0f},{arrow_y:.0f} {x1 - 2:.0f},{arrow_y - 5:.0f} {x1 - 2:.0f},{arrow_y + 5:.0f}",
               "-stroke", "none", "-gravity", "NorthWest", "-annotate", f"+{x0:.0f}+{arrow_y + 6:.0f}",
               "it faces its local +z"]
    p.title("The same robot from its right side\n/key 0 r.rhand 0 0 0 60 0 0   /key 0 r.lhand 0 0 0 -60 0 0")
    return p.render([f"/robot r 0 0 {DEPTH} 0 90 0", "/key 0 r.rhand 0 0 0 60 0 0",
                     "/key 0 r.lhand 0 0 0 -60 0 0"] + paint("r"), tmp, "robot_side")


def human_front(tmp):
    p = Panel(840, mirror=True)
    for at in [(0, 0), (0, -105), (0, 35), (33, 28), (-33, 28)]:
        p.pivot(*at)
    p.label((10, 60), "head: sphere r 20\ncentre (0 22 0), pivot (0 140 0)", -90, 100)
    p.label((33, 0), "rhand: cylinder r 7, h 90\ncentre (0 -45 0), pivot (33 133 0)", -90, 20)
    p.label((0, 0), "root: the /human position", -90, -35)
    p.label((0, -105), "body pivot (0 -105 0) in root:\nthe feet", -90, -95)
    p.label((-33, 0), "lhand: cylinder r 7, h 90\ncentre (0 -45 0), pivot (-33 133 0)", 90, 20)
    p.label((-12, -60), "body: cylinder r 25, h 140\ncentre (0 70 0)", 90, -80)
    p.title("Human from the front (turned to face the camera: its right hand is on the image's left)\n"
            "white dots: pivots; sizes in scene units (cm); positions in the parent's frame")
    return p.render([f"/human h 0 0 {DEPTH} 0 180 0"] + paint("h"), tmp, "human_front")


def save(images, out):
    subprocess.run(["convert"] + [str(i) for i in images] + ["+append", "-strip", str(out)], check=True)
    print(out)


def main():
    with tempfile.TemporaryDirectory() as tmp:
        save([robot_front(tmp), robot_side(tmp)], ROOT / "docs/model-robot.png")
        save([human_front(tmp)], ROOT / "docs/model-human.png")


if __name__ == "__main__":
    main()
