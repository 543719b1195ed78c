"""The mechanism on the sweep card: fixed guides with their rails, the coupler curves, the links, slider
blocks, pins and names at the first angle the linkage stands, each moving part tagged for the page's
script, which moves it to the positions the card's JSON carries; the names stand away from the links at
every angle (their offsets travel in the JSON too).  The symbols are the sheets' own
(:mod:`drafting.render.symbols`).
"""

from __future__ import annotations

import math

from constructions.geometry import Vec

from ..layout.wrap import text_at
from ..render.drawing import DOT_R, PIN_R
from ..render.paper import Circle, Line, Polygon, Polyline
from ..render.style import LABEL, measure, rich
from ..render.symbols import BLOCK_H, BLOCK_L, ground_side, ground_symbol, hatching

LABEL_OFFSET = (1.6, -1.8)


def _hull_order(local: dict[str, Vec]) -> list[str]:
    """A plate's points in order round its centroid (its outline)."""
    cx = sum(p.x for p in local.values()) / len(local)
    cy = sum(p.y for p in local.values()) / len(local)
    return sorted(local, key=lambda n: math.atan2(local[n].y - cy, local[n].x - cx))


def _away_from(p: tuple[float, float], others: list[tuple[float, float]]) -> tuple[float, float]:
    """Of down, left, right and up (paper), the direction furthest in angle from the lines p -> others."""
    return ground_side([math.atan2(q[1] - p[1], q[0] - p[0]) for q in others if q != p])


LABEL_DIRECTIONS = tuple(-math.pi / 4 + j * math.pi / 4 for j in range(8))
"""Where a joint's name may stand (paper angles, y down), up-right first: the drafter's habit."""


def label_offset(spans, incident: list[float]) -> tuple[float, float]:
    """Where the name ``spans`` of a point starts (baseline, from the point, paper mm): centred on the
    direction furthest from the ``incident`` directions (paper angles of the lines leaving the point),
    just clear of its pin."""
    def gap(a: float) -> float:
        return min((abs((a - b + math.pi) % (2 * math.pi) - math.pi) for b in incident), default=math.pi)
    best = max(LABEL_DIRECTIONS, key=lambda a: (round(gap(a), 9), -LABEL_DIRECTIONS.index(a)))
    ext = measure(spans)
    d = (math.cos(best), math.sin(best))
    r = PIN_R + 0.7 + abs(d[0]) * ext.width / 2 + abs(d[1]) * ext.height / 2
    cx, cy = r * d[0], r * d[1]
    return round(cx - ext.width / 2, 3), round(cy - (ext.top + ext.bottom) / 2, 3)


def guides(card) -> None:
    """Each fixed guide: its centre line and, for a block, rails along the block's whole travel."""
    for sl in card.m.slides:
        if sl.on is not None or sl.joint not in card.pos:
            continue
        d = (math.cos(sl.angle), -math.sin(sl.angle))
        nrm = (-d[1], d[0])
        g = card.paper((sl.through.x * card.per_m, sl.through.y * card.per_m))
        ts = [(q[0] - g[0]) * d[0] + (q[1] - g[1]) * d[1]
              for q in (card.paper(p) for p in card.pos[sl.joint] if p is not None)]
        if not ts:
            continue
        a0, a1 = min(ts) - BLOCK_L / 2 - 4.0, max(ts) + BLOCK_L / 2 + 4.0
        card.static.append(Line(g[0] + a0 * d[0], g[1] + a0 * d[1], g[0] + a1 * d[0], g[1] + a1 * d[1], "centre",
                                f"sweep guide {sl.joint}:centre line"))
        if sl.number is None:
            continue
        for sn in (1.0, -1.0):
            off = (nrm[0] * sn * BLOCK_H / 2, nrm[1] * sn * BLOCK_H / 2)
            p1 = (g[0] + a0 * d[0] + off[0], g[1] + a0 * d[1] + off[1])
            card.static.append(Line(*p1, g[0] + a1 * d[0] + off[0], g[1] + a1 * d[1] + off[1], "guide",
                                    f"sweep guide {sl.joint}:rail"))
            h = hatching(p1, d, a1 - a0, (nrm[0] * sn, nrm[1] * sn), f"sweep guide {sl.joint}:hatch")
            if h is not None:
                card.static.append(h)

def traces(card) -> list[dict]:
    """The coupler curve of each point fixed to a link (not a joint): the whole path thin, broken at
    gaps, and over it the part traced from the first angle to the slider's."""
    m, count = card.m, card.count
    card.traced = [a.name for a in m.attached if a.name in card.pos and a.name not in m.ground
                   and not any(a.name in lk.joints for lk in m.links)]
    out: list[dict] = []
    for name in card.traced:
        i = 0
        while i < count:
            if card.pos[name][i] is None:
                i += 1
                continue
            j = i
            while j < count and card.pos[name][j] is not None:
                j += 1
            run = [card.paper(p) for p in card.pos[name][i:j]]
            if card.closed and i == 0 and j == count:
                run.append(run[0])
            if len(run) >= 2:
                card.static.append(Polyline(tuple(run), "path", f"sweep path of {name} {len(out) + 1}"))
                tid = f"sw-trace-{len(out)}"
                card.tag(Polyline(tuple(run[:1]) * 2, "series 4", f"sweep trace {len(out)}"), tid, "sw-trace")
                out.append({"id": tid, "at": name, "from": i, "to": j})
            i = j
    return out

def bodies(card) -> dict[str, list]:
    """Links (lines, or plates through all their points), slider blocks, pins, labels, fixed pivots."""
    m, pos = card.m, card.pos
    links, blocks, pins, labels = [], [], [], []
    for lk in m.links:
        local = m.local(lk.number)
        order = [x for x in (_hull_order(local) if len(local) > 2 else lk.joints) if x in pos]
        if len(order) < 2:
            continue
        lid = f"sw-link-{lk.number}"
        card.tag(Line(*card.at(order[0]), *card.at(order[1]), "link", f"sweep link {lk.number}") if len(order) == 2
                 else Polygon(tuple(card.at(x) for x in order), "link", f"sweep link {lk.number}"), lid)
        links.append({"id": lid, "pts": order})
    for sl in m.slides:
        if sl.number is None or sl.joint not in pos:
            continue
        dirs: list = []
        for i in range(card.count):
            if pos[sl.joint][i] is None:
                dirs.append(None)
            elif sl.on is None:
                dirs.append(sl.angle)
            else:                                    # a block on a slot turns with the slotted link
                a, b = m.link(sl.on).joints
                pa, pb = pos[a][i] if a in pos else None, pos[b][i] if b in pos else None
                dirs.append(None if pa is None or pb is None else
                            math.atan2(pb[1] - pa[1], pb[0] - pa[0]) + sl.angle)
        bid = f"sw-block-{sl.number}"
        c0 = card.at(sl.joint)
        card.tag(Polygon((c0, c0, c0, c0), "block", f"sweep block {sl.number}"), bid)
        blocks.append({"id": bid, "at": sl.joint, "dir": dirs, "l": BLOCK_L, "h": BLOCK_H})
    for gname, gp in m.ground.items():
        p = card.paper((gp.x * card.per_m, gp.y * card.per_m))
        away = _away_from(p, [card.at(lk.other(gname)) for lk in m.links
                              if gname in lk.joints and lk.other(gname) in pos])
        card.static += ground_symbol(p, away, f"sweep pivot {gname}")[0]
        spans = rich(gname, LABEL, pivot_digits=True)
        others = [card.at(lk.other(gname)) for lk in m.links if gname in lk.joints and lk.other(gname) in pos]
        incident = [math.atan2(q[1] - p[1], q[0] - p[0]) for q in others if q != p]
        dx, dy = label_offset(spans, incident + [math.atan2(away[1], away[0]) + t for t in (-0.6, 0.0, 0.6)])
        card.static.append(text_at(p[0] + dx, p[1] + dy, spans, style="label", region="sweep",
                                   name=f"sweep label {gname}"))
    joints = {j for lk in m.links for j in lk.joints} | {sl.joint for sl in m.slides}
    for name in pos:
        if name in m.ground or not (name in joints or name in card.traced):
            continue
        pid, lid = f"sw-pin-{name}", f"sw-label-{name}"
        card.tag(Circle(*card.at(name), PIN_R, "pin", f"sweep pin {name}") if name in joints
                 else Circle(*card.at(name), DOT_R, "dot", f"sweep pin {name}"), pid)
        pins.append({"id": pid, "at": name})
        spans = rich(name, LABEL, pivot_digits=True)
        offsets = [_label_at(card, name, i, spans, blocks) for i in range(card.count)]
        x, y = card.at(name)
        dx, dy = offsets[card.first]
        card.tag(text_at(x + dx, y + dy, spans, style="label", region="sweep", name=f"sweep label {name}"), lid)
        labels.append({"id": lid, "at": name, "off": offsets})
    return {"links": links, "blocks": blocks, "pins": pins, "labels": labels}

def _label_at(card, name: str, i: int, spans, blocks: list[dict]) -> tuple[float, float]:
    """The offset of ``name``'s label at slider angle ``i``: away from the links and blocks there."""
    p = card.pos[name][i]
    if p is None:
        return LABEL_OFFSET
    incident = []
    for lk in card.m.links:
        local = card.m.local(lk.number)
        if name in local:
            for other in local:
                q = card.pos[other][i] if other in card.pos and other != name else None
                if q is not None and (q[0], q[1]) != (p[0], p[1]):
                    incident.append(math.atan2(-(q[1] - p[1]), q[0] - p[0]))
    for b in blocks:
        if b["at"] == name and b["dir"][i] is not None:
            incident += [-b["dir"][i], math.pi - b["dir"][i]]
    return label_offset(spans, incident)
