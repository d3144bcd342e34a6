#!/usr/bin/env python3
"""Writes scenes/cluttered-2.toml and scenes/cluttered-2.path: the very cluttered environment 2.

The scene is built from a few design numbers (the tube's margin, its centre line as straight runs and
bends, where the plates stand); the tube's curved walls become many short boxes, which is why the
scene file is generated rather than typed. The path is the design's own way through: the part rides
the tube's centre line (both ends on it, so in a bend its middle cuts inside), rolls for the first
opening, turns and rolls for the second and goes through each along its normal. It proves the scene
solvable (a test runs check-path on it); it is not used by any planner or operator.

The operator's guide is written by hand below (GUIDE): a person's rough gesture along the way, at
most 12 keyframes, that cuts the bends' corners through the walls.

Usage: scenes/make-cluttered-2.py [--margin M] [--out-dir DIR]
"""

import argparse
import math
import os
import textwrap

# --- design ---------------------------------------------------------------------------------------
STEM = (1.0, 0.2, 0.2)  # the T-part's stem, x in [-0.6, 0.4]
HEAD = (0.2, 0.6, 0.2)  # its head at the +x end, x in [0.4, 0.6]
HALF_LENGTH = 0.6
WALL = 0.05  # the tube's wall thickness
PLATE = 0.04  # the plates' thickness
TUBE_Z = 1.0  # height of the tube's axis
RADIUS = 3.0  # bend radius of the tube's centre line
STEP_DEG = 3.0  # each bend's walls: one box per 3 degrees
# The tube's centre line from its mouth at the origin, heading +x: straight runs (metres) and bends
# (degrees, + to the left). Two S-bends: left and back, right and back.
CENTRE_LINE = [("straight", 0.6), ("bend", 45.0), ("bend", -45.0), ("straight", 0.4),
               ("bend", -45.0), ("bend", 45.0), ("straight", 0.5)]
PLATE_1_AFTER = 2.2  # plate 1 stands this far after the tube's exit, across the way
PLATE_1_ROLL = 45.0  # its opening is turned about the way's axis
PLATE_2_AFTER = 4.5  # plate 2's centre, after the exit
PLATE_2_RPY = (-30.0, 0.0, -35.0)  # plate 2 turned about z, its opening about the plate's normal
GOAL_AFTER = (5.8, -0.2)  # the goal, from the exit (x, y)
SIDE = 0.45  # the bounds: this far sideways from the way
UP = 0.25  # and this far up or down from the tube's axis

START = ((-0.9, 0.25, 1.2), (0.0, 0.0, 20.0))


def guide(exit_x, exit_y):
    """The operator's guide, by hand: a glance at the scene, the bends' corners cut."""
    ex, ey = exit_x, exit_y
    return [
        ((-0.9, 0.25, 1.2), (0, 0, 20)),
        ((-0.9, 0.0, 1.0), None),
        ((1.75, 0.23, 1.0), (0, 0, 22.5)),  # into the first bend
        ((3.7, 1.6, 1.0), None),  # out of the first S
        ((5.9, 0.6, 1.0), (0, 0, -22.5)),  # through the second S
        ((ex + 0.9, ey, 1.0), None),  # out of the tube
        ((ex + 1.0, ey, 1.0), (PLATE_1_ROLL, 0, 0)),  # roll for the first opening
        ((ex + 3.0, ey, 1.0), (PLATE_1_ROLL, 0, 0)),  # through it
        ((ex + 3.2, ey + 0.2, 1.0), PLATE_2_RPY),  # turn and roll for the second
        ((ex + 3.9, ey + 0.35, 1.0), PLATE_2_RPY),
        ((ex + 5.1, ey - 0.35, 1.0), PLATE_2_RPY),  # through it
        ((ex + GOAL_AFTER[0], ey + GOAL_AFTER[1], 1.0), None),
    ]


# --- small geometry -------------------------------------------------------------------------------
def quat_rpy(roll, pitch, yaw):
    """Quaternion (x, y, z, w) of R = Rz(yaw) Ry(pitch) Rx(roll), radians (URDF's rpy)."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def slerp(a, b, t):
    dot = sum(x * y for x, y in zip(a, b))
    if dot < 0:
        b, dot = tuple(-x for x in b), -dot
    if dot > 0.9995:
        q = tuple(x + t * (y - x) for x, y in zip(a, b))
    else:
        th = math.acos(dot)
        sa, sb = math.sin((1 - t) * th) / math.sin(th), math.sin(t * th) / math.sin(th)
        q = tuple(sa * x + sb * y for x, y in zip(a, b))
    n = math.sqrt(sum(x * x for x in q))
    return tuple(x / n for x in q)


def fmt(v):
    s = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0.0" if s in ("-0", "0") else (s if "." in s else s + ".0")


def vec(v):
    return "[" + ", ".join(fmt(x) for x in v) + "]"


def box(size, pos, yaw_deg=None, rpy=None, note=""):
    s = f"  {{ box = {vec(size)}, position = {vec(pos)}"
    if rpy is not None:
        s += f", rpy_deg = {vec(rpy)}"
    elif yaw_deg is not None and abs(yaw_deg) > 1e-9:
        s += f", rpy_deg = {vec((0.0, 0.0, yaw_deg))}"
    s += " },"
    return s + (f"  # {note}" if note else "")


# --- the tube's centre line -----------------------------------------------------------------------
def centre_line(ds=0.01):
    """Points (x, y, heading) every ds along the centre line, and the pieces (kind, start pose, length
    or angle)."""
    x, y, h = 0.0, 0.0, 0.0
    pts = [(x, y, h)]
    pieces = []
    for kind, amount in CENTRE_LINE:
        pieces.append((kind, (x, y, h), amount))
        if kind == "straight":
            n = max(1, round(amount / ds))
            for _ in range(n):
                x += amount / n * math.cos(h)
                y += amount / n * math.sin(h)
                pts.append((x, y, h))
        else:
            turn = math.radians(amount)
            length = RADIUS * abs(turn)
            n = max(1, round(length / ds))
            side = 1.0 if turn > 0 else -1.0
            cx, cy = x - side * RADIUS * math.sin(h), y + side * RADIUS * math.cos(h)
            for i in range(1, n + 1):
                hh = h + turn * i / n
                pts.append((cx + side * RADIUS * math.sin(hh), cy - side * RADIUS * math.cos(hh), hh))
            x, y, h = pts[-1]
    return pts, pieces


def tube_walls(pieces, inner_width, inner_height):
    off = inner_width / 2 + WALL / 2
    height = inner_height + 2 * WALL  # the side walls reach into the top and bottom plates
    lines = []
    for k, (kind, (x, y, h), amount) in enumerate(pieces):
        if kind == "straight":
            mx, my = x + amount / 2 * math.cos(h), y + amount / 2 * math.sin(h)
            for side, name in ((1, "left"), (-1, "right")):
                px, py = mx - side * off * math.sin(h), my + side * off * math.cos(h)
                lines.append(box((amount + 0.02, WALL, height), (px, py, TUBE_Z), math.degrees(h),
                                 note=f"run {k + 1}, {name}"))
        else:
            turn = math.radians(amount)
            side = 1.0 if turn > 0 else -1.0
            cx, cy = x - side * RADIUS * math.sin(h), y + side * RADIUS * math.cos(h)
            n = round(abs(amount) / STEP_DEG)
            for i in range(n):
                hm = h + turn * (i + 0.5) / n
                for wall, name in ((1, "left"), (-1, "right")):
                    # radius of this wall's centre: the left wall is inside a left bend
                    r = RADIUS - side * wall * off
                    outer = r + WALL / 2
                    length = 2 * outer * math.tan(abs(turn) / n / 2) + 0.004
                    px = cx + side * r * math.sin(hm)
                    py = cy - side * r * math.cos(hm)
                    lines.append(box((length, WALL, height), (px, py, TUBE_Z), math.degrees(hm),
                                     note=f"bend {k + 1}, {name}"))
    return lines


def wall_with_hole(x, y_lo, y_hi, hole_y, hole_w, hole_h, thickness, z_top=2.1):
    """A wall across x = const from y_lo to y_hi, floor to z_top, with a hole centred at (hole_y,
    TUBE_Z)."""
    lines = []
    left = y_hi - (hole_y + hole_w / 2)
    right = (hole_y - hole_w / 2) - y_lo
    lines.append(box((thickness, left, z_top), (x, hole_y + hole_w / 2 + left / 2, z_top / 2),
                     note="left of the hole"))
    lines.append(box((thickness, right, z_top), (x, y_lo + right / 2, z_top / 2),
                     note="right of the hole"))
    above = z_top - (TUBE_Z + hole_h / 2)
    lines.append(box((thickness, hole_w, above), (x, hole_y, z_top - above / 2), note="above the hole"))
    below = TUBE_Z - hole_h / 2
    lines.append(box((thickness, hole_w, below), (x, hole_y, below / 2), note="below the hole"))
    return lines


def rot_z(v, deg):
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    return (c * v[0] - s * v[1], s * v[0] + c * v[1], v[2])


def rot_rpy(v, rpy):
    r, p, y = (math.radians(a) for a in rpy)
    x0, y0, z0 = v
    y1, z1 = math.cos(r) * y0 - math.sin(r) * z0, math.sin(r) * y0 + math.cos(r) * z0
    x2, z2 = math.cos(p) * x0 + math.sin(p) * z1, -math.sin(p) * x0 + math.cos(p) * z1
    return (math.cos(y) * x2 - math.sin(y) * y1, math.sin(y) * x2 + math.cos(y) * y1, z2)


def framed_opening(centre, rpy, opening_w, opening_h, plate_rpy, hole=0.8):
    """The frame that fills a square hole (side `hole`) around an opening turned by rpy: two end
    pieces and two long pieces, in the opening's frame."""
    lines = []
    ends_w = (hole * 1.5 - opening_w) / 2
    for sign, name in ((1, "left end"), (-1, "right end")):
        local = (0.0, sign * (opening_w / 2 + ends_w / 2), 0.0)
        p = rot_rpy(local, rpy)
        lines.append(box((PLATE, ends_w, hole * 1.5),
                         (centre[0] + p[0], centre[1] + p[1], centre[2] + p[2]), rpy=rpy,
                         note=f"frame, {name} of the opening"))
    long_h = (hole * 1.5 - opening_h) / 2
    for sign, name in ((1, "above"), (-1, "below")):
        local = (0.0, 0.0, sign * (opening_h / 2 + long_h / 2))
        p = rot_rpy(local, rpy)
        lines.append(box((PLATE, opening_w, long_h),
                         (centre[0] + p[0], centre[1] + p[1], centre[2] + p[2]), rpy=rpy,
                         note=f"frame, {name} the opening"))
    return lines


def plate_with_square_hole(centre, yaw, s_lo, s_hi, hole=0.8, z_top=2.1):
    """A plate through `centre` turned by yaw about z, spanning s in [s_lo, s_hi] along its own y
    axis, with a square hole (side `hole`) about the centre."""
    lines = []
    u = rot_z((0.0, 1.0, 0.0), yaw)
    for lo, hi, name in ((hole / 2, s_hi, "left of the hole"), (s_lo, -hole / 2, "right of the hole")):
        mid = (lo + hi) / 2
        lines.append(box((PLATE, hi - lo, z_top),
                         (centre[0] + mid * u[0], centre[1] + mid * u[1], z_top / 2),
                         rpy=(0.0, 0.0, yaw), note=name))
    above = z_top - (TUBE_Z + hole / 2)
    lines.append(box((PLATE, hole, above), (centre[0], centre[1], z_top - above / 2),
                     rpy=(0.0, 0.0, yaw), note="above the hole"))
    below = TUBE_Z - hole / 2
    lines.append(box((PLATE, hole, below), (centre[0], centre[1], below / 2), rpy=(0.0, 0.0, yaw),
                     note="below the hole"))
    return lines


# --- the hand-made path ---------------------------------------------------------------------------
def along_tube(pts, ds):
    """Poses of the part riding the centre line: its ends on the line, its middle on their chord."""
    states = []
    n = len(pts)
    k = round(HALF_LENGTH / ds)
    for i in range(0, n, 3):
        a = pts[max(0, i - k)]
        b = pts[min(n - 1, i + k)]
        if i - k < 0:  # not yet in: extend the line backwards along x
            a = (pts[0][0] - (k - i) * ds, pts[0][1], 0.0)
        if i + k > n - 1:  # coming out: extend it forwards along the exit's heading
            extra = (i + k - (n - 1)) * ds
            b = (pts[-1][0] + extra * math.cos(pts[-1][2]), pts[-1][1] + extra * math.sin(pts[-1][2]),
                 pts[-1][2])
        heading = math.atan2(b[1] - a[1], b[0] - a[0])
        states.append(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, TUBE_Z, quat_rpy(0, 0, heading)))
    return states


def line(p0, q0, p1, q1, step=0.05):
    n = max(1, math.ceil(math.dist(p0, p1) / step))
    return [(*(a + (b - a) * i / n for a, b in zip(p0, p1)), slerp(q0, q1, i / n))
            for i in range(1, n + 1)]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--margin", type=float, default=0.04, help="tube margin around the part (m)")
    ap.add_argument("--out-dir", default=os.path.dirname(os.path.abspath(__file__)))
    args = ap.parse_args()
    m = args.margin
    inner_w, inner_h = HEAD[1] + 2 * m, HEAD[2] + 2 * m

    pts, pieces = centre_line()
    ex, ey, eh = pts[-1]
    assert abs(eh) < 1e-9, "the tube must end heading +x"
    ys = [p[1] for p in pts]
    p1x = ex + PLATE_1_AFTER
    p2 = (ex + PLATE_2_AFTER, ey, TUBE_Z)
    n2 = rot_z((1.0, 0.0, 0.0), PLATE_2_RPY[2])  # plate 2's normal
    # The way: the tube's centre line, then through each opening along its normal.
    way_ys = ys + [p2[1] - 0.8 * n2[1], p2[1] + 0.8 * n2[1]]
    y_lo, y_hi = min(way_ys) - SIDE, max(way_ys) + SIDE
    reach_lo, reach_hi = y_lo - 1.0, y_hi + 1.0  # walls reach past the bounds
    goal = tuple(round(v, 4) for v in (ex + GOAL_AFTER[0], ey + GOAL_AFTER[1], TUBE_Z))
    x_lo, x_hi = -1.4, goal[0] + 0.3

    out = []
    w = out.append
    w("# The very cluttered environment 2 of Blin et al., \"Tuning Interaction in Motion Planning with")
    w("# Contact\" (section G, figure 11, Table V): tandem's own geometry after the paper's description.")
    w("# Metres, z up. Generated by scenes/make-cluttered-2.py (edit that, not this file).")
    w("#")
    w("# The object is a T-shaped part, not environment 1's L: a stem 1.0 m long with a 0.2 m square")
    w("# section and, at its +x end, a head 0.2 m deep, 0.6 m wide and 0.2 m high; 1.2 m long in all.")
    w("# Seen along its stem it is a 0.6 x 0.2 m rectangle, the only way it fits through the openings.")
    w("#")
    length = sum(a if k == "straight" else RADIUS * math.radians(abs(a)) for k, a in CENTRE_LINE)
    para = (f"From the entry room (x < 0) it goes through a long tube, {length:.1f} m along its centre "
            f"line, whose inner section is {inner_w:.2f} x {inner_h:.2f} m: {m * 100:.0f} cm of margin on "
            "every side, so in the tube the part can barely move. The tube makes two S-bends (45 "
            f"degrees left and back, then right and back, radius {RADIUS:.0f} m): the part has to turn "
            "with it, and no straight motion gets far along it. Then come two thin plates (4 cm) "
            f"with one small opening each, 0.7 x 0.3 m. The first, {PLATE_1_AFTER} m after the tube, "
            f"is turned {PLATE_1_ROLL:.0f} degrees about the way's axis: the part has to roll once it "
            "is out of the tube. The second is rotated about two axes, -35 degrees about z and -30 "
            "degrees about its own normal: the part has to turn and roll again, between the plates, "
            "to pass. The goal is beyond. The bounds keep the reference point within "
            f"{SIDE} m of the way sideways and {UP} m up or down; the walls reach past them, so the "
            "part cannot get round.")
    for text in textwrap.wrap(para, 98):
        w("# " + text)
    w("")
    w('name = "cluttered-2"')
    w('description = "Very cluttered environment 2 of the 2016 papers (T-shaped part, long tight tube with'
      ' two S-bends, two rotated plates with small openings)"')
    w("")
    w("[space]")
    w('kind = "se3"')
    w(f"min = {vec((x_lo, y_lo, TUBE_Z - UP))}")
    w(f"max = {vec((x_hi, y_hi, TUBE_Z + UP))}")
    w("# Check motions every 0.3% of the diagonal (about 4 cm) and 0.54 degrees.")
    w("resolution = 0.003")
    w("")
    w("[object]")
    w('name = "T-part"')
    w('color = "#e6e6e6"')
    w("shapes = [")
    w(f"  {{ box = {vec(STEM)}, position = [-0.1, 0.0, 0.0] }},  # the stem, x in [-0.6, 0.4]")
    w(f"  {{ box = {vec(HEAD)}, position = [0.5, 0.0, 0.0] }},  # the head, at the +x end")
    w("]")
    w("")
    w("[[obstacle]]")
    w('name = "floor"')
    w('color = "#b8b0a0"')
    w(f"box = {vec((x_hi - x_lo + 2.0, reach_hi - reach_lo, 0.1))}")
    w(f"position = {vec(((x_lo + x_hi) / 2, (reach_lo + reach_hi) / 2, -0.05))}")
    w("")
    w("# The walls at both ends of the tube, each with the tube's mouth cut out.")
    w("[[obstacle]]")
    w('name = "entry-wall"')
    w('color = "#3a62c8"')
    w("shapes = [")
    out.extend(wall_with_hole(-WALL / 2, reach_lo, reach_hi, 0.0, inner_w, inner_h, WALL))
    w("]")
    w("")
    w("# The tube's side walls follow its centre line, one box per 3 degrees in the bends; its top and")
    w("# bottom are plates over the whole length.")
    w("[[obstacle]]")
    w('name = "tube"')
    w('color = "#30c8c0"')
    w("shapes = [")
    roof_y_lo, roof_y_hi = min(ys) - inner_w, max(ys) + inner_w
    for z, name in ((TUBE_Z + inner_h / 2 + WALL / 2, "top"), (TUBE_Z - inner_h / 2 - WALL / 2, "bottom")):
        w(box((ex, roof_y_hi - roof_y_lo, WALL), (ex / 2, (roof_y_lo + roof_y_hi) / 2, z),
              note=f"the tube's {name}"))
    out.extend(tube_walls(pieces, inner_w, inner_h))
    w("]")
    w("")
    w("[[obstacle]]")
    w('name = "exit-wall"')
    w('color = "#3a62c8"')
    w("shapes = [")
    out.extend(wall_with_hole(ex - WALL / 2, reach_lo, reach_hi, ey, inner_w, inner_h, WALL))
    w("]")
    w("")
    w(f"# Plate 1 across the way at x = {fmt(p1x)}; its opening, on the tube's axis, is turned")
    w(f"# {PLATE_1_ROLL:.0f} degrees about x: a frame so turned fills a square hole (0.8 m) in the plate.")
    w("[[obstacle]]")
    w('name = "plate-1"')
    w('color = "#c83a3a"')
    w("shapes = [")
    out.extend(plate_with_square_hole((p1x, ey, TUBE_Z), 0.0, reach_lo - ey, reach_hi - ey))
    out.extend(framed_opening((p1x, ey, TUBE_Z), (PLATE_1_ROLL, 0.0, 0.0), 0.7, 0.3, None))
    w("]")
    w("")
    w(f"# Plate 2 through {vec(p2)}, turned {PLATE_2_RPY[2]:.0f} degrees about z; its opening, centred")
    w(f"# there, is turned {PLATE_2_RPY[0]:.0f} degrees about the plate's normal (rpy {vec(PLATE_2_RPY)}).")
    w("[[obstacle]]")
    w('name = "plate-2"')
    w('color = "#c83a3a"')
    w("shapes = [")
    c35 = math.cos(math.radians(PLATE_2_RPY[2]))
    out.extend(plate_with_square_hole(p2, PLATE_2_RPY[2], (reach_lo - ey) / c35, (reach_hi - ey) / c35))
    out.extend(framed_opening(p2, PLATE_2_RPY, 0.7, 0.3, None))
    w("]")
    w("")
    w("[start]")
    w(f"position = {vec(START[0])}")
    w(f"rpy_deg = {vec(START[1])}")
    w("")
    w("[goal]")
    w(f"position = {vec(goal)}")
    w("rpy_deg = [0.0, 0.0, 0.0]")
    w("")
    w("# A simulated operator's guide, placed by hand: line the part up with the tube's mouth, push it")
    w("# through the tube, turning it roughly with the bends (cutting their corners), roll it once out to")
    w("# match the first opening and push it through, then turn and roll it to match the second one,")
    w("# push it through, and bring it to the goal. Coarse on purpose (a person's gesture, not a path):")
    w("# the planner does the fine motion.")
    w("[guide]")
    w("keyframes = [")
    for p, rpy in guide(ex, ey):
        s = f"  {{ position = {vec(p)}"
        if rpy is not None:
            s += f", rpy_deg = {vec(rpy)}"
        w(s + " },")
    w("]")
    w("")
    w("[planner]")
    w('name = "birrt"')
    w("# Keep the last valid configuration of a blocked extension (the papers' Add_Tree).")
    w('extend = "last-valid"')
    w("time_limit = 120.0")

    with open(os.path.join(args.out_dir, "cluttered-2.toml"), "w") as f:
        f.write("\n".join(out) + "\n")

    # The path.
    deg = math.radians
    q_id = quat_rpy(0, 0, 0)
    states = [(*START[0], quat_rpy(*(deg(a) for a in START[1])))]
    states += line(START[0], states[0][3], (-0.9, 0.0, TUBE_Z), q_id)
    states += line((-0.9, 0.0, TUBE_Z), q_id, (-0.6, 0.0, TUBE_Z), q_id)
    states += along_tube(pts, 0.01)
    q1 = quat_rpy(deg(PLATE_1_ROLL), 0, 0)
    last = states[-1][:3]
    states += line(last, states[-1][3], (ex + 0.75, ey, TUBE_Z), q_id)
    states += line((ex + 0.75, ey, TUBE_Z), q_id, (ex + 1.0, ey, TUBE_Z), q1)
    states += line((ex + 1.0, ey, TUBE_Z), q1, (p1x + 0.75, ey, TUBE_Z), q1)
    q2 = quat_rpy(*(deg(a) for a in PLATE_2_RPY))
    before = (p2[0] - 0.8 * n2[0], p2[1] - 0.8 * n2[1], TUBE_Z)
    after = (p2[0] + 0.8 * n2[0], p2[1] + 0.8 * n2[1], TUBE_Z)
    states += line((p1x + 0.75, ey, TUBE_Z), q1, before, q2)
    states += line(before, q2, after, q2)
    states += line(after, q2, goal, q_id)
    with open(os.path.join(args.out_dir, "cluttered-2.path"), "w") as f:
        for s in states:
            f.write(" ".join(f"{v:.10g}" for v in (*s[:3], *s[3])) + "\n")
    print(f"cluttered-2: tube {length:.2f} m, exit at ({ex:.4f}, {ey:.4f}), {len(states)} path states")


if __name__ == "__main__":
    main()
