"""Mechanisms the tests share -- the notes' toggle linkage and compound six-bars, slotted links, ternary
links, a joint carried along two lines -- built once, so that every check of them (construction, dyad
chain, constraint equations) looks at the same mechanism."""

from __future__ import annotations

import math

from constructions.geometry import Vec
from constructions.mechanisms.model import Attached, Branch, Link, Mechanism, Slide

MM = 1e-3


def quick_return(offset=0.0, branch=1, block=True, ram=True):
    """Slotted-lever quick-return: crank O1A (link 1) carries a block (link 2) sliding in the slot of the
    lever O2P (link 3); the lever drives the ram Q (block 5) on a fixed guide through PQ (link 4)."""
    links = [Link(1, ("O1", "A"), 0.05), Link(3, ("O2", "P"), 0.25)]
    slides = [Slide(2 if block else None, "A", Vec(0, 0), 0.0, on=3, offset=offset)]
    branches = {"A": Branch(branch, ("O2",))}
    if ram:
        links.append(Link(4, ("P", "Q"), 0.1))
        slides.append(Slide(5, "Q", Vec(0, 0.24), 0.0))
        branches["Q"] = Branch(1, ("P",))
    return Mechanism({"O1": Vec(0, 0.1), "O2": Vec(0, 0)}, tuple(links), tuple(slides), (), 1, branches)


def rocker_with_slot():
    """A four-bar O1-B-C-O2 whose rocker (link 3) has a slot along it; a block (link 6) pinned at D on the
    rocker O3D (link 5) slides in that slot: D is where the circle about O3 meets the moving slot."""
    return Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0.0), "O3": Vec(0.12, 0.02)},
                     (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "C"), 0.1), Link(3, ("O2", "C"), 0.08),
                      Link(5, ("O3", "D"), 0.06)),
                     (Slide(6, "D", Vec(0, 0), 0.0, on=3),), (), 1,
                     {"C": Branch(1, ("B", "O2")), "D": Branch(1, ("O3",))})


def slanted_slot():
    """The block meeting a moving slot, with the slot turned 20 deg from the rocker and 8 mm off it."""
    m = rocker_with_slot()
    return Mechanism(m.ground, m.links, (Slide(6, "D", Vec(0, 0), math.radians(20), on=3, offset=0.008),),
                     (), 1, m.branches)


def watt_six_bar():
    """Watt I: four-bar O1-B-C-O2 with a ternary coupler BCE and a ternary rocker O2CF; the dyad E-G-F
    (links 4 and 5) hangs from the two ternary links."""
    return Mechanism({"O1": Vec(0, 0), "O2": Vec(0.09, 0.0)},
                     (Link(1, ("O1", "B"), 0.025), Link(2, ("B", "C"), 0.08), Link(3, ("O2", "C"), 0.06),
                      Link(4, ("E", "G"), 0.07), Link(5, ("F", "G"), 0.06)),
                     (), (Attached("E", 2, "B", 0.05, math.radians(35)),
                          Attached("F", 3, "O2", 0.05, math.radians(-40))), 1,
                     {"C": Branch(1, ("B", "O2")), "G": Branch(1, ("E", "F"))})


def ternary_posed_by_other_points():
    """Stephenson-like: the ternary link 2 (base joints B, C, third point E) is found through E (circle of
    the rocker O2E) and only then gives C, which drives the slider D through CD."""
    return Mechanism({"O1": Vec(0, 0), "O2": Vec(0.08, 0.05)},
                     (Link(1, ("O1", "B"), 0.02), Link(2, ("B", "C"), 0.07), Link(3, ("O2", "E"), 0.05),
                      Link(4, ("C", "D"), 0.08)),
                     (Slide(5, "D", Vec(0, -0.02), 0.0),), (Attached("E", 2, "B", 0.06, math.radians(30)),), 1,
                     {"E": Branch(1, ("B", "O2")), "D": Branch(1, ("C",))})


def slot_and_guide(pin=False):
    """A PRP dyad: a four-bar whose rocker (link 3) has a slot along it; the joint J is carried by a block
    (link 5, or a bare pin) in that slot and by a block (link 6) on a fixed vertical guide -- J is where
    the slot and the guide cross."""
    return Mechanism({"O1": Vec(0, 0), "O2": Vec(0.1, 0.0)},
                     (Link(1, ("O1", "B"), 0.03), Link(2, ("B", "C"), 0.1), Link(3, ("O2", "C"), 0.08)),
                     (Slide(5, "J", Vec(0, 0), 0.0, on=3), Slide(6, "J", Vec(0.07, 0.0), math.pi / 2)), (), 1,
                     {"C": Branch(1, ("B", "O2"))})


def toggle_linkage(c_branch: int = -1, d_branch: int = 1) -> Mechanism:
    """The notes' toggle linkage (as in tests/test_compound.py): four-bar O1-B-C-O2 driving slider D."""
    return Mechanism(
        ground={"O1": Vec(0, 0), "O2": Vec(60 * MM, 40 * MM)},
        links=(Link(1, ("O1", "B"), 20 * MM), Link(2, ("B", "C"), 50 * MM), Link(3, ("O2", "C"), 30 * MM),
               Link(4, ("C", "D"), 60 * MM)),
        slides=(Slide(5, "D", Vec(0, 0), 0.0),), attached=(), crank=1,
        branches={"C": Branch(c_branch, ("B", "O2")), "D": Branch(d_branch, ("C",))})


def six_bar(e_branch: int = -1) -> Mechanism:
    """Stephenson-like six-bar: four-bar O1-B-C-O2 whose coupler is the ternary link BCD (three binary
    links in a rigid triangle: D is an RRR dyad on two MOVING joints), then the dyad D-E-O3 in series;
    point P on DE.  Every dyad closes at every crank angle (crank-rocker, Grashof)."""
    return Mechanism(
        ground={"O1": Vec(0, 0), "O2": Vec(60 * MM, 0), "O3": Vec(50 * MM, 40 * MM)},
        links=(Link(1, ("O1", "B"), 15 * MM), Link(2, ("B", "C"), 55 * MM), Link(3, ("O2", "C"), 40 * MM),
               Link(4, ("B", "D"), 40 * MM), Link(5, ("C", "D"), 30 * MM),
               Link(6, ("D", "E"), 30 * MM), Link(7, ("O3", "E"), 30 * MM)),
        slides=(), attached=(Attached("P", 6, "D", 20 * MM, math.radians(30)),
                             Attached("Q", 7, "E", 12 * MM, math.radians(-90))), crank=1,
        branches={"C": Branch(1, ("B", "O2")), "D": Branch(1, ("B", "C")), "E": Branch(e_branch, ("D", "O3"))})


def watt_chain() -> Mechanism:
    """Two RRR dyads in series sharing joint C (a compound hinge): C from B and O2, E from C and O3."""
    return Mechanism(
        ground={"O1": Vec(0, 0), "O2": Vec(60 * MM, 0), "O3": Vec(110 * MM, 40 * MM)},
        links=(Link(1, ("O1", "B"), 15 * MM), Link(2, ("B", "C"), 55 * MM), Link(3, ("O2", "C"), 40 * MM),
               Link(4, ("C", "E"), 50 * MM), Link(5, ("O3", "E"), 35 * MM)),
        slides=(), attached=(Attached("P", 2, "B", 30 * MM, math.radians(20)),), crank=1,
        branches={"C": Branch(1, ("B", "O2")), "E": Branch(1, ("C", "O3"))})


def four_bar(o1, o2, crank, coupler, rocker, branch, attached=()):
    """O1-B crank (link 1), B-C coupler (2), O2-C rocker (3); branch +1: C left of B->O2."""
    return Mechanism({"O1": Vec(*o1), "O2": Vec(*o2)},
                     (Link(1, ("O1", "B"), crank), Link(2, ("B", "C"), coupler), Link(3, ("O2", "C"), rocker)),
                     (), tuple(attached), 1, {"C": Branch(branch, ("B", "O2"))})


def slider_crank(o1, crank, coupler, guide_point, guide_angle, branch, attached=()):
    """O1-B crank (1), B-C coupler (2), slider block 3 at C on the guide; branch +1: C ahead of B."""
    return Mechanism({"O1": Vec(*o1)}, (Link(1, ("O1", "B"), crank), Link(2, ("B", "C"), coupler)),
                     (Slide(3, "C", Vec(*guide_point), guide_angle),), tuple(attached), 1,
                     {"C": Branch(branch, ("B",))})
