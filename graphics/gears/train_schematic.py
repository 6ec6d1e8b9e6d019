"""A gear train in the side-view symbols of the textbooks.

The main axis is a centre line (an ordinary train's gears each stand on their own, a
centre distance above the one that drives them). A gear is a rectangle as tall as its pitch
diameter about its own axis, its face across; a ring is its two rims, teeth inward, and a
web out to its hub. A planet stands on a pin of the arm at its carrier radius, drawn above the
main axis and again below it. The arm is a bar from its hub out to its pins, on the side
facing the input.
The input's shaft and those of the members a ratio or torque is asked of leave along the
axis, the first plane's to the left and the last's to the right. The fixed member is
hatched to the ground: a ring by its rims, a sun by its face.

A gear turning square to the main axis (a bevel planet, a pinion on a square side shaft)
and the gears it meshes are drawn as bevel gears (:mod:`.bevel_view`), the arm as the cage.

The file gives no axial places, so gears in mesh share a plane and each further gear on a
shaft takes the next; radii are to scale (in modules where no gear gives its module), the
planes are not.
"""

from __future__ import annotations

from tarsim.constructions.gears.train import GearTrain
from tarsim.constructions.units import LENGTH_UNITS
from tarsim.constructions.narration import words
from ..figure import Figure, Path
from ..drafts import label_placer
from ..fitting import to_sheet
from ..scales import draw_caption, nice_per_cm
from ..symbols import draw_hatched_band
from .bevel_view import bevel_view, draw_bevels

__all__ = ["draw_train_schematic"]

_PLANE = 18.0      # mm between axial planes
_FACE = 6.0        # a gear's face, mm
_RIM = 3.0         # a ring's rim, mm
_ROOM = 55.0       # mm the farthest pitch line is drawn out to, at most
_SHAFT = 14.0      # mm a shaft runs past the outermost plane


def draw_train_schematic(train: GearTrain, title: str, outputs: tuple[int, ...] = (),
                         per_cm: float | None = None) -> Figure:
    """The side view of ``train``, with its caption and radius scale ``per_cm`` (by default
    the nice scale that fits its room, fitted to the sheet it is drawn on); the input's
    shaft and those of ``outputs`` leave the drawing along the main axis."""
    plane = _planes(train)
    unit = train.units.length if train.sized else "modules"
    per_unit = 1.0 / LENGTH_UNITS[unit] if train.sized else 1.0
    radius = {g.number: float(train.pitch_radius(g.number)) * per_unit for g in train.gears}
    axis = {m: y * per_unit for m, y in _axes(train).items()}
    reach = max(abs(axis[m]) + r for m, r in radius.items())
    if per_cm is None:
        return to_sheet(lambda at: draw_train_schematic(train, title, outputs, at),
                        nice_per_cm(reach, _ROOM))
    mm = 10.0 / per_cm
    fig = Figure(0.0, 0.0, title=title)
    placer = label_placer(fig)   # drafting: as on a blank page
    bevel = bevel_view(train, {m: p * _PLANE for m, p in plane.items()},
                       lambda g: radius[g] * mm)
    xs = [p * _PLANE for m, p in plane.items() if bevel is None or m not in bevel.x]
    if bevel is not None:                 # a bevel gear's place and its radius either side
        xs += [x + s * radius[g] * mm for g, x in bevel.x.items() for s in (1, -1)]
    left, right = min(xs) - _SHAFT, max(xs) + _FACE + _SHAFT
    for y in sorted({-axis[m] * mm for m in axis} if not train.planetary else {0.0}):
        fig.add(Path(((left - 4.0, y), (right + 4.0, y)), "reference"))   # the axes
    rings = {g.number for g in train.gears if _is_ring(train, g.number)}
    fixed = set(train.body(train.fixed)) if train.fixed is not None else set()
    labels: list[tuple[str, tuple[float, float]]] = []

    def box(x: float, y0: float, y1: float, face: float = _FACE) -> None:
        pts = ((x, y0), (x + face, y0), (x + face, y1), (x, y1))
        fig.add(Path(pts, "link", closed=True))
        placer.block_path([*pts, pts[0]], 0.6)

    if bevel is not None:
        draw_bevels(fig, train, bevel, lambda g: radius[g] * mm,
                    lambda pts: placer.block_path(pts, 0.6), labels)
        for g in fixed & set(bevel.toward):       # a fixed bevel gear: its web held
            back = radius[g] * mm - abs(bevel.web(g) - bevel.x[g])
            draw_hatched_band(fig, (bevel.web(g), -back), (bevel.web(g), back),
                              (-bevel.toward[g], 0.0), depth=2.5)
    for g in train.gears:
        if bevel is not None and g.number in bevel.x:
            continue
        first, last = _span(train, plane, g.number)
        x, r, y = first * _PLANE, radius[g.number] * mm, -axis[g.number] * mm
        face = (last - first) * _PLANE + _FACE
        if g.number in rings:
            for s in (1.0, -1.0):                     # the two rims, teeth toward the axis
                box(x, s * r, s * (r + _RIM), face)
            web = x + face
            if g.number in fixed:                     # held by its rims to the housing
                for s in (1.0, -1.0):
                    edge = s * (r + _RIM)
                    draw_hatched_band(fig, (x - 2.0, edge), (web + 2.0, edge), (0.0, s))
            else:                                     # a web out to its hub on the axis
                fig.add(Path(((web, -(r + _RIM)), (web + 3.0, -(r + _RIM)),
                              (web + 3.0, r + _RIM), (web, r + _RIM)), "link"))
            labels.append((str(g.number), (web, -(r + _RIM / 2))))
            continue
        ys = (y, -y) if train.planetary and train.carried(g.number) else (y,)
        for cy in ys:
            box(x, cy - r, cy + r, face)
        if g.number in fixed:                          # a fixed sun: its face held
            draw_hatched_band(fig, (x, y - r), (x, y + r), (-1.0, 0.0), depth=2.5)
        labels.append((str(g.number), (x + face, y - 0.5 * r)))
    _shafts(train, fig, plane, axis, mm, (left, right), rings,
            (train.input_member, *((train.second[0],) if train.second else ()), *outputs),
            bevel)
    if bevel is not None and bevel.planets:
        _cage(train, fig, bevel, plane, labels)
    elif train.arm is not None and train.planetary:
        xa = plane[train.arm] * _PLANE + _FACE / 2
        # A pin for each carrier radius the planets stand at (two planets in series on the
        # arm stand at two), all on the arm's one bar.
        pins = sorted({-axis[g.number] * mm for g in train.gears if g.carrier is not None},
                      key=abs)
        pin, far = pins[0], pins[-1]
        # each pin out through the farthest plane of the planets it carries
        reach = {cy: max(plane[g.number] for g in train.gears if train.carried(g.number)
                         and -axis[g.number] * mm == cy) * _PLANE + _FACE for cy in pins}
        for s in (1.0, -1.0):
            fig.add(Path(((xa, 0.0), (xa, s * far), (reach[far], s * far)), "link"))
            for cy in pins[:-1]:
                fig.add(Path(((xa, s * cy), (reach[cy], s * cy)), "link"))
        for m in train.body(train.arm):         # a gear keyed to the arm's hub
            if m != train.arm:
                fig.add(Path(((xa, 0.0), (plane[m] * _PLANE, 0.0)), "link"))
        if train.arm in fixed:
            draw_hatched_band(fig, (xa, far), (xa, -far), (-1.0, 0.0))
        labels.append((str(train.arm), (xa, 0.5 * pin)))
    placer.block_drawn()        # the axes, the shafts, the webs and the arm as well
    for text, at in labels:
        placer.place(text, at, prefer=(0.0, 3.1416, 1.57), spread=0.7, gap=1.5, size=3.6,
                     italic=False)
    held = (words("member {member} fixed (hatched)", member=str(train.fixed))
            if train.fixed is not None else words("no member fixed: two speeds given")
            if train.second is not None else words("every axis fixed in the housing"))
    draw_caption(fig, words("{name}: the train", name=train.name),
                 [held, words("radii to scale, the planes apart")],
                 per_cm=per_cm, unit=unit, scale_name="Radius scale")
    return fig


def _is_ring(train: GearTrain, number: int) -> bool:
    """True for a gear that another meshes inside (the one of more teeth in an internal
    mesh)."""
    return any(m.internal and number in (m.a, m.b) and train.gear(number).teeth == max(
        train.gear(m.a).teeth, train.gear(m.b).teeth) for m in train.meshes)


def _cage(train: GearTrain, fig: Figure, bevel, plane: dict[int, int],
          labels: list[tuple[str, tuple[float, float]]]) -> None:
    """The arm as a differential's cage: from the web of the gear on its hub (or its own
    hub) out past the bevel planets' backs and across to their spindles."""
    hub = [m for m in train.body(train.arm) if m != train.arm]
    start = (bevel.web(hub[0]) if hub and hub[0] in bevel.toward
             else plane[hub[0]] * _PLANE + _FACE if hub else plane[train.arm] * _PLANE)
    far = max(bevel.cage(p) for p in bevel.planets)
    end = max(bevel.x[p] for p in bevel.planets)
    for s in (1.0, -1.0):
        fig.add(Path(((start, s * far), (end, s * far)), "link"))
    if not hub:
        fig.add(Path(((start, far), (start, -far)), "link"))
    if train.fixed is not None and train.arm in train.body(train.fixed):
        draw_hatched_band(fig, (start, -far), (start, far), (-1.0, 0.0))
    labels.append((str(train.arm), (0.5 * (start + min(bevel.x[p] for p in bevel.planets)),
                                    -far)))


def _shafts(train: GearTrain, fig: Figure, plane, axis, mm: float, span: tuple[float, float],
            rings: set[int], ends: tuple[int, ...], bevel=None) -> None:
    """The shafts: a compound gear's between its planes, and those of ``ends`` (the input
    and the outputs) out along the main axis (a bevel gear's from its web, a gear's on a
    square side shaft with its bevel teeth)."""
    for body in train.bodies:
        gears = [m for m in body if m != train.arm]
        if len(gears) > 1:                          # gears on one shaft: joined between planes
            y = -axis[gears[0]] * mm
            a = min(plane[m] for m in gears) * _PLANE + _FACE
            b = max(plane[m] for m in gears) * _PLANE
            for cy in ((y, -y) if train.planetary and train.carried(gears[0]) else (y,)):
                fig.add(Path(((a, cy), (b, cy)), "link"))
    # The shafts that leave: the input's and the outputs', the first (by plane) to the left
    # and the last to the right; along the main axis, or in an ordinary train each on its
    # own axis.
    leaving = sorted({train.body(m)[0] for m in ends
                      if not (train.fixed is not None and m in train.body(train.fixed))
                      and not (train.planetary and train.carried(m))
                      and not train.square(m)
                      and (m == train.arm or not train.planetary
                           or axis.get(m, 0.0) == 0.0 or m in train.off_axis)},
                     key=lambda m: plane[m])
    for k, m in enumerate(leaving[:1] + leaving[1:][-1:]):
        x, y, face = plane[m] * _PLANE, -axis.get(m, 0.0) * mm, _FACE
        left = k == 0 and (len(leaving) > 1 or m == train.arm)
        if bevel is not None and m in bevel.toward:     # from its web, away from its teeth
            x, face = bevel.web(m), 0.0
            left = bevel.toward[m] > 0
        if left:
            fig.add(Path(((span[0], y), (x + (_FACE / 2 if m == train.arm else 0.0), y)),
                         "link"))
        else:
            start = x + face + (3.0 if m in rings else 0.0)
            fig.add(Path(((start, y), (span[1], y)), "link"))


def _planes(train: GearTrain) -> dict[int, int]:
    """An axial plane for each member: gears in mesh share one, unless the gear would
    overlap another in it (a second planet at another carrier radius), and each further
    gear on a shaft takes the next; the arm the one before them all."""
    plane: dict[int, int] = {}
    todo: list[int] = []
    bands = _bands(train)

    def clear(m: int, p: int) -> bool:
        return not any(q == p and _overlap(bands[m], bands[k]) for k, q in plane.items()
                       if k != train.arm)

    for g in train.gears:
        if g.number in plane:
            continue
        plane[g.number] = max(plane.values(), default=0) + 1
        todo.append(g.number)
        while todo:
            m = todo.pop(0)
            for mesh in train.meshes:
                for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                    if a == m and b not in plane:
                        plane[b] = (plane[m] if clear(b, plane[m])
                                    else max(plane.values()) + 1)
                        todo.append(b)
            for k in train.body(m):
                if k not in plane and k != train.arm:
                    plane[k] = max(plane.values()) + 1
                    todo.append(k)
    if train.arm is not None:
        plane[train.arm] = 0
    return plane


def _bands(train: GearTrain) -> dict[int, list[tuple[float, float]]]:
    """The radii each gear fills in the side view, above the main axis and below (a ring its
    pitch circle alone, its rim being outside every gear it holds)."""
    axis = _axes(train)
    out = {}
    for g in train.gears:
        r, y = float(train.pitch_radius(g.number)), axis[g.number]
        if _is_ring(train, g.number):
            out[g.number] = [(y + r, y + r), (y - r, y - r)]
        elif train.planetary and train.carried(g.number):
            out[g.number] = [(y - r, y + r), (-y - r, -y + r)]
        else:
            out[g.number] = [(y - r, y + r)]
    return out


def _overlap(a: list[tuple[float, float]], b: list[tuple[float, float]]) -> bool:
    """True if two gears' bands overlap (gears in mesh only touch)."""
    return any(min(h1, h2) - max(l1, l2) > 1e-9 * max(abs(h1), abs(h2), 1e-300)
               for l1, h1 in a for l2, h2 in b)


def _span(train: GearTrain, plane: dict[int, int], number: int) -> tuple[int, int]:
    """The planes a gear's face runs across: its own, and for a gear on the main axis those
    of the planets it meshes (a ring or a sun that planets at two carrier radii mesh side
    by side)."""
    near = [plane[number]]
    if train.planetary and not train.carried(number) and number not in train.off_axis:
        near += [plane[b] for m in train.meshes for a, b in ((m.a, m.b), (m.b, m.a))
                 if a == number]
    return min(near), max(near)


def _coaxial_partner(train: GearTrain, number: int) -> int | None:
    """The gear an ordinary reverted train names on one axis with ``number``, if any."""
    if train.coaxial is None or number not in train.coaxial:
        return None
    a, b = train.coaxial
    return b if number == a else a


def _axes(train: GearTrain) -> dict[int, float]:
    """Each gear's axis above the main axis (size units): 0 on the main axis, the carrier
    radius for a planet (one in series, meshing planets alone, a centre distance beyond
    the planet it meshes); in an ordinary train (or on a planetary train's side shaft) the
    first gear's at 0 and each next one a centre distance above the one that drives it, but
    a reverted train's output on its input's axis (``coaxial``)."""
    side = train.off_axis                   # a side shaft: a centre distance off the axis
    first = next((g.number for g in train.gears
                  if not (train.planetary and train.carried(g.number)) and g.number not in side),
                 train.gears[0].number)
    y: dict[int, float] = {first: 0.0}
    if train.planetary:      # a planet meshing a main-axis gear stands at its carrier radius
        y.update({g.number: 0.0 for g in train.gears
                  if not train.carried(g.number) and g.number not in side})
        for mesh in train.meshes:
            for p, c in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                if train.carried(p) and not train.carried(c) and c not in side:
                    rp, rc = (float(train.pitch_radius(n)) for n in (p, c))
                    y.setdefault(p, rc - rp if mesh.internal else rc + rp)
    grew = True
    while grew:
        grew = False
        for mesh in train.meshes:
            for a, b in ((mesh.a, mesh.b), (mesh.b, mesh.a)):
                if a in y and b not in y:
                    ra, rb = (float(train.pitch_radius(n)) for n in (a, b))
                    partner = _coaxial_partner(train, b)
                    if train.planetary and not train.carried(b) and b not in side:
                        y[b] = 0.0
                    elif partner in y:        # a reverted train's output: back on the input's
                        y[b] = y[partner]
                    else:
                        y[b] = y[a] + (abs(ra - rb) if mesh.internal else ra + rb)
                    grew = True
        for g in train.gears:
            for k in train.body(g.number):
                if g.number not in y and k in y and k != train.arm:
                    y[g.number] = y[k]
                    grew = True
    return {g.number: y.get(g.number, 0.0) for g in train.gears}
