"""The vector equations of the polygons as the notes write them, with their known/unknown marks, and the
captions that give each one's directions: V_C = V_B + V_CB (velocity), A_C^n + A_C^t = A_B + A_CB^n +
A_CB^t (acceleration), and their forms on a guide, in a slot and about a moving centre.
"""

from __future__ import annotations

from ..mechanisms.assembly import CircleAndGuide
from ..mechanisms.model import Mechanism
from ..record import Term, VectorEquation
from .common import component_name


def velocity_equation(arms, j: str, m: Mechanism, guided: bool, coincident: str = "") -> VectorEquation:
    """V_J = V_P + V_JP with the notes' marks; both centres moving: V_P + V_JP = V_Q + V_JQ; on a moving
    slot: V_P + V_JP = V_JG + V_J,JG (JG the slotted link's point under J)."""
    if coincident:
        (_, c), = arms
        left = (Term("V", coincident, True, True), Term("V", f"{j}{coincident}", False, True))
        if c in m.ground:
            return VectorEquation((Term("V", j, False, True),), left)
        return VectorEquation((Term("V", c, True, True), Term("V", f"{j}{c}", False, True)), left)
    moving = [(l, c) for l, c in arms if c not in m.ground]
    fixed = [(l, c) for l, c in arms if c in m.ground]
    if guided or fixed:
        left = (Term("V", j, False, True),)
        (_, c), = moving if moving else fixed[:1]
        if c in m.ground:
            return VectorEquation(left, (Term("V", f"{j}{c}", False, True),))
        return VectorEquation(left, (Term("V", c, True, True), Term("V", f"{j}{c}", False, True)))
    (_, p), (_, q) = moving
    return VectorEquation((Term("V", p, True, True), Term("V", f"{j}{p}", False, True)),
                          (Term("V", q, True, True), Term("V", f"{j}{q}", False, True)))


def velocity_slot_equation(j: str, jg: str, c: str, m: Mechanism) -> VectorEquation:
    """V_JG = V_J + V_JG,J about a fixed centre; V_C + V_JG,C = V_J + V_JG,J about a moving one."""
    right = (Term("V", j, True, True), Term("V", f"{jg}{j}", False, True))
    if c in m.ground:
        return VectorEquation((Term("V", jg, False, True),), right)
    return VectorEquation((Term("V", c, True, True), Term("V", f"{jg}{c}", False, True)), right)


def velocity_caption(eq: VectorEquation, arms, j: str, m: Mechanism, step) -> str:
    links = " and ".join(f"link {l.number} ({l.label})" for l, _ in arms)
    dirs = [f"V_{j}{c} \u22a5 {c}{j}" if c not in m.ground else f"V_{j} \u22a5 {c}{j}" for _, c in arms]
    if isinstance(step, CircleAndGuide):
        dirs.append(f"V_{j} \u2225 guide" if step.slide.on is None else f"V_{j}{step.coincident} \u2225 slot")
    return (f"Relative velocity equation on {links}: {eq.text(marks=False)}, with {', '.join(dirs)}; "
            f"two unknown magnitudes.")


def _known_terms(p: str, tip: str) -> tuple[Term, ...]:
    """The known acceleration of a joint as the notes write it: the crank tip as A_B^n + A_B^t."""
    if p == tip:
        return (Term("A", p, True, True, "n"), Term("A", p, True, True, "t"))
    return (Term("A", p, True, True),)


def acceleration_slot_equation(m: Mechanism, tip: str, j: str, jg: str, c: str) -> VectorEquation:
    """A_JG^n + A_JG^t = A_J + A_JG,J^c + A_JG,J^s about a fixed centre; about a moving one the centre's
    known acceleration and A_JG,C^n + A_JG,C^t on the left (``tip`` is the crank's tip)."""
    right = (Term("A", j, True, True), Term("A", f"{jg}{j}", True, True, "c"),
             Term("A", f"{jg}{j}", False, True, "s"))
    if c in m.ground:
        left = (Term("A", jg, True, True, "n"), Term("A", jg, False, True, "t"))
    else:
        left = _known_terms(c, tip) + (Term("A", f"{jg}{c}", True, True, "n"), Term("A", f"{jg}{c}", False, True, "t"))
    return VectorEquation(left, right)


def acceleration_equation(m: Mechanism, tip: str, arms, j: str, guided: bool, coincident: str = "") -> VectorEquation:
    """The notes' acceleration equations with their marks:
    slider:   A_J(x✓) = A_P + A_JP^n(✓✓) + A_JP^t(x✓)
    rocker:   A_J^n(✓✓) + A_J^t(x✓) = A_P + A_JP^n(✓✓) + A_JP^t(x✓)
    two moving centres: A_P + A_JP^n + A_JP^t = A_Q + A_JQ^n + A_JQ^t."""

    def side(centre: str) -> tuple[Term, ...]:
        if centre in m.ground:
            return (Term("A", j, True, True, "n"), Term("A", j, False, True, "t"))
        return _known_terms(centre, tip) + (Term("A", f"{j}{centre}", True, True, "n"),
                                            Term("A", f"{j}{centre}", False, True, "t"))
    if guided and coincident:
        (_, c), = arms
        slot = (Term("A", coincident, True, True), Term("A", f"{j}{coincident}", True, True, "c"),
                Term("A", f"{j}{coincident}", False, True, "s"))
        return VectorEquation(side(c), slot)
    if guided:
        (_, c), = arms
        return VectorEquation((Term("A", j, False, True),), side(c))
    (_, p), (_, q) = arms
    if p in m.ground:
        p, q = q, p
    return VectorEquation(side(q), side(p)) if q in m.ground else VectorEquation(side(p), side(q))


def acceleration_caption(m: Mechanism, eq: VectorEquation, arms, j: str, guided: bool, step=None) -> str:
    """The equation's caption: the links it stands on and the direction of each component."""
    links = " and ".join(f"link {l.number} ({l.label})" for l, _ in arms)
    dirs = []
    for link, c in arms:
        n, t = component_name(j, c, "n", m), component_name(j, c, "t", m)
        dirs.append(f"{n} \u2225 {c}{j} towards {c}, {t} \u22a5 {c}{j}")
    if guided and step is not None and step.slide.on is not None:
        jg = step.coincident
        dirs.append(f"A_{j}{jg}^s \u2225 slot, the Coriolis component A_{j}{jg}^c = 2 \u03c9_{step.slide.on} "
                    f"\u00d7 V_{j}{jg}")
    elif guided:
        dirs.append(f"A_{j} \u2225 guide")
    return (f"Relative acceleration equation on {links}: {eq.text(marks=False)}, with {'; '.join(dirs)}; "
            f"two unknown magnitudes.")
