"""One rigid body held by supports, solved graphically: Culmann's method, or three-force concurrency.

The body (a boom, a bracket, a lever) carries known loads and couples and is held by supports, each a
force of unknown magnitude along a known line or, for a pin, of unknown direction too:

- a *two-force member* (:data:`MEMBER`) pinned to the body at one point and to a fixed point at the
  other end, with no load between: its force acts along the member (tension or compression);
- a *roller* (:data:`ROLLER`) pushes square to the surface it rolls on, along a given normal (it cannot
  pull: a roller that would have to is reported);
- a *guide* (:data:`GUIDE`), a pin in a fixed slot, pushes square to the slot, either way;
- a *pin* (:data:`PIN`) to the frame: a force of unknown magnitude and direction.

Statics gives three equations, so the supports must bring exactly three unknown scalars, and their lines
must not all meet in one point or all be parallel (then they cannot balance a moment about that point, or
a force across them: *improperly constrained*).  Both are checked first (:func:`check_supports`).

The construction, as a drafter draws it:

1. the resultant R of the known loads, with its line of action (the loads laid off head to tail give
   R; its line lies where R's moment equals the loads' moment, Varignon);
2. three supports of known lines -- *Culmann's method*: R's line meets the line of one support a at K,
   the other two lines meet at L; the body is in equilibrium under R, F_a and the *Culmann force*
   F_b + F_c, which acts through L -- three forces, so they are concurrent and the Culmann force acts
   along KL.  The force triangle R + F_a + F_KL = 0 closes on the directions of a and KL, and F_KL is
   resolved into F_b and F_c along their lines;
3. a pin and one support of known line -- *three-force concurrency*: R's line and the support's line
   meet at I, so the pin force passes through the pin and I; the force triangle closes on those two
   directions.  Where R is (nearly) parallel to the support's line, I runs away: the support's force comes
   from the moments about the pin instead (force x perpendicular distance), as it does when the loads
   reduce to a couple (no line for R);
4. where the loads reduce to a couple, or where no pairing gives Culmann a well-placed K and L (R along one
   support's line with the other two parallel), *Ritter's method*: two supports' lines meet at L, the
   moments about L give the third support's force, and the polygon closes along the other two.

Of the three ways to pair the supports in Culmann's method the best-conditioned is drawn (the sines at K,
at L and of the triangle, and KL not too short), preferring, among those at least half as well
conditioned, the one that keeps K and L nearest the body.  The forces are measured off the polygon (the
:class:`~constructions.quantities.Measured` of each support is its force on the body).  The body and its
supports are :mod:`.rigid_body`, the drawing's pieces :mod:`.free_body_drawing`; the independent check is
:mod:`constructions.forces.free_body_check`.
"""

from __future__ import annotations

import math

from ..formatting import Formatter
from ..geometry import Vec
from ..entities import Arrow, Point, Role, TrialLine
from ..record import StepKind, Value, VectorEquation
from ..tolerance import CONDITION_SHARE, DECISION, PARALLEL_SINE, WARN_SINE
from .board import force_value, meet, resultant
from .free_body_drawing import FORCE, ORIGIN, SPACE, BodyDrawing, term
from .rigid_body import PIN, FreeBodyAnalysis, RigidBody, Support, check_supports, si, sine


class _Construction(BodyDrawing):
    """The free body drawn by one of the methods: Culmann's, three-force concurrency, moments about the pin,
    Ritter's moments about L, or none for a body nothing loads."""

    def culmann(self, pairing: tuple) -> None:
        """Culmann's method with ``pairing`` (a, b, c, K, L): R x a = K, b x c = L."""
        b = self.b
        sup = list(b.supports)
        lines = [b.line(s) for s in sup]
        u_r = self.R_line[1]
        ia, ib, ic, K, L = pairing
        a, bb, cc = sup[ia], sup[ib], sup[ic]
        ua, ub, uc = lines[ia][1], lines[ib][1], lines[ic][1]
        self.points.update({"K": K, "L": L})
        self.conds += [sine(u_r, ua), sine(ub, uc)]
        self.method = "Culmann"
        self.then(f"Culmann's method: R meets the line of {a.name} at K; the lines of {bb.name} and {cc.name} "
                  f"meet at L. The {b.name} is held by three forces, R, {a.name} and F_KL = {bb.name} + "
                  f"{cc.name} (through L); three forces in equilibrium meet in one point, so F_KL acts along KL, "
                  f"the Culmann line (dashed).",
                  Point("K", Role.LABEL, SPACE, K, "K"), Point("L", Role.LABEL, SPACE, L, "L"),
                  TrialLine("Culmann line", Role.AUXILIARY, SPACE, K, L - K, None))
        self.lay_off(VectorEquation((term("R", True, True), term(a.name, False, True),
                                     term("F_KL", False, True)), ()), ua)
        x = self.close("a", (a.name, ua, self.along(a)), ("F_KL", L - K, "\u2225 KL"), self.tip, "its end", "x",
                       role=Role.AUXILIARY)
        y = self.close("bc", (bb.name, ub, self.along(bb)), (cc.name, uc, self.along(cc)), x, "x", "y",
                       "Resolve F_KL (from x to O_f). ",
                       equation=VectorEquation((term("F_KL", True, True),),
                                               (term(bb.name, False, True), term(cc.name, False, True))))
        self.answer([(a.name, self.tip, x), (bb.name, x, y), (cc.name, y, ORIGIN)])

    def concurrency(self, pin: Support, other: Support) -> None:
        b = self.b
        A = b.points[pin.at]
        pb, ub = b.line(other)
        p_r, u_r = self.R_line
        s = sine(u_r, ub)
        if s < WARN_SINE:
            self.moments_about_pin(pin, other, f"R is (nearly) parallel to the line of {other.name}, so they "
                                               f"meet too far away to draw. ")
            return
        I = meet(p_r, u_r, pb, ub)
        self.points["I"] = I
        self.conds.append(s)
        self.method = "three-force concurrency"
        self.then(f"Three forces hold the {b.name}: R, {other.name} and the pin force {pin.name}. R meets the line "
                  f"of {other.name} at I; three forces in equilibrium meet in one point, so {pin.name} acts along "
                  f"{pin.at}I.",
                  Point("I", Role.LABEL, SPACE, I, f"I ({b.name})"),
                  TrialLine(f"line {pin.name}", Role.TRIAL, SPACE, A, I - A, pin.name))
        self.lay_off(VectorEquation((term("R", True, True), term(other.name, False, True),
                                     term(pin.name, False, True)), ()), ub)
        x = self.close("pin", (other.name, ub, self.along(other)), (pin.name, I - A, f"\u2225 {pin.at}I ({b.name})"),
                       self.tip, "its end", "x")
        self.answer([(other.name, self.tip, x), (pin.name, x, ORIGIN)])

    def moments_about_pin(self, pin: Support, other: Support, why: str) -> None:
        """The support's force from the moments about the pin (force x perpendicular distance); the pin
        force closes the polygon."""
        b = self.b
        A = b.points[pin.at]
        pb, ub = b.line(other)
        _, mo = resultant(self.knowns, self.couple, A)
        arm = (pb - A).cross(ub)
        f_b = ub * (-mo / arm)
        self.method = "moments"
        self.conds.append(min(1.0, abs(arm) / self.size))
        self.then(f"{why}Moments about the pin {pin.at}: {other.name} \u00d7 its arm $h balances the moment of the "
                  f"loads about {pin.at} ($m), so {other.name} = $f.",
                  values={"h": Value("length", abs(arm)), "m": Value("torque", abs(mo)), "f": force_value(f_b.norm())})
        eq = VectorEquation(self.rterm() + (term(other.name, True, True), term(pin.name, False, False)), ())
        self.start_polygon(eq, ub)
        end = self.tip + f_b
        self.answer([(other.name, self.tip, end), (pin.name, end, ORIGIN)])

    def ritter(self, why: str) -> None:
        """Moments about L (Ritter's method), where the other two supports' lines meet: the third support's
        force times its arm balances the moment of the loads about L; the polygon then closes along the
        other two.  For loads that reduce to a couple, and where Culmann's K or L runs away (R along a
        support's line with the other two parallel)."""
        b = self.b
        sup = list(b.supports)
        lines = [b.line(s) for s in sup]
        _, ia, ib, ic, L, arm = _ritter_pairing(b, lines)
        a, bb, cc = sup[ia], sup[ib], sup[ic]
        _, mo = resultant(self.knowns, self.couple, L)
        f_a = lines[ia][1] * (-mo / arm)
        self.points["L"] = L
        self.conds += [sine(lines[ib][1], lines[ic][1]), min(1.0, abs(arm) / self.size)]
        self.method = "moments"
        self.then(f"{why}The lines of {bb.name} and {cc.name} meet at L; moments about L: {a.name} \u00d7 its arm $h "
                  f"balances the moment of the loads about L ($m), so {a.name} = $f.",
                  Point("L", Role.LABEL, SPACE, L, "L"),
                  values={"h": Value("length", abs(arm)), "m": Value("torque", abs(mo)), "f": force_value(f_a.norm())})
        eq = VectorEquation(self.rterm() + (term(a.name, True, True), term(bb.name, False, True),
                                             term(cc.name, False, True)), ())
        self.start_polygon(eq, lines[ib][1])
        start = self.tip
        end = start + f_a
        self.then(f"Lay off {a.name} from {'the end' if self.knowns else 'O_f'}.",
                  Arrow(f"polygon result {a.name}", Role.RESULT, FORCE, start, end, a.name))
        self.tip = end
        y = self.close("bc", (bb.name, lines[ib][1], self.along(bb)), (cc.name, lines[ic][1], self.along(cc)),
                       end, "its end", "y")
        self.forces[a.name] = f_a
        self.answer([(bb.name, end, y), (cc.name, y, ORIGIN)])

    def unloaded(self) -> None:
        self.method = "no load"
        for s in self.b.supports:
            self.forces[s.name] = ORIGIN
        self.then(f"Nothing loads the {self.b.name}: every support force is zero.", kind=StepKind.ANSWER)


def _culmann_pairing(body: RigidBody, lines, p_r: Vec, u_r: Vec):
    """The pairing to draw as (condition, a, b, c, K, L): K = R's line x a, L = b x c; the best conditioned
    (sines at K, at L, of the triangle, |KL| over the body's size), and among those at least half as well
    conditioned the one with K and L nearest the body.  None when no pairing gives both points."""
    size = body.size
    pts = list(body.points.values()) + list(body.fixed.values())
    cands = []
    for ia in range(3):
        ib, ic = [k for k in range(3) if k != ia]
        (pa, ua), (pb, ub), (pc, uc) = lines[ia], lines[ib], lines[ic]
        s_k, s_l = sine(u_r, ua), sine(ub, uc)
        if s_k < PARALLEL_SINE or s_l < PARALLEL_SINE:
            continue
        K = meet(p_r, u_r, pa, ua)
        L = meet(pb, ub, pc, uc)
        n = (L - K).norm()
        if n <= DECISION * size:
            continue
        cond = min(s_k, s_l, sine(ua, L - K), n / size)
        every = pts + [K, L]
        extent = math.hypot(max(p.x for p in every) - min(p.x for p in every),
                            max(p.y for p in every) - min(p.y for p in every))
        cands.append((cond, extent, ia, ib, ic, K, L))
    if not cands:
        return None
    best = max(c[0] for c in cands)
    pick = min((c for c in cands if c[0] >= CONDITION_SHARE * best), key=lambda c: (c[1], c[2]))
    return (pick[0],) + pick[2:]


def _ritter_pairing(body: RigidBody, lines):
    """(condition, a, b, c, L, arm) for moments about L = b x c: the pairing with the best of the sine at L
    and a's arm about L over the body's size (check_supports leaves at least one with both non-zero)."""
    best = None
    for ia in range(3):
        ib, ic = [k for k in range(3) if k != ia]
        s = sine(lines[ib][1], lines[ic][1])
        if s < PARALLEL_SINE:
            continue
        L = meet(*lines[ib], *lines[ic])
        arm = (lines[ia][0] - L).cross(lines[ia][1])
        cond = min(s, abs(arm) / body.size)
        if best is None or cond > best[0]:
            best = (cond, ia, ib, ic, L, arm)
    return best


def free_body_analysis(body: RigidBody, fmt: Formatter | None = None) -> FreeBodyAnalysis:
    """Solve ``body`` graphically: the supports are checked (:func:`check_supports`), then Culmann's method
    (three supports of known line), three-force concurrency (a pin and one support of known line), or
    moments (about the pin, or about L by Ritter's method) where the loads reduce to a couple or Culmann's
    points run away; ``fmt(kind, value)`` writes values in error messages."""
    fmt = fmt or si
    check_supports(body, fmt)
    d = _Construction(body, fmt)
    d.given()
    d.free_body()
    d.resultant()
    pins = [s for s in body.supports if s.kind == PIN]
    if not d.knowns and d.couple == 0.0:
        d.unloaded()
    elif pins:
        other = next(s for s in body.supports if s.kind != PIN)
        if d.R_line is None:
            d.moments_about_pin(pins[0], other, "The loads reduce to a couple (no resultant force). ")
        else:
            d.concurrency(pins[0], other)
    elif d.R_line is None:
        d.ritter("The loads reduce to a couple (no resultant force). ")
    else:
        lines = [body.line(s) for s in body.supports]
        culmann = _culmann_pairing(body, lines, *d.R_line)
        if culmann is None or culmann[0] < WARN_SINE and _ritter_pairing(body, lines)[0] > culmann[0]:
            d.ritter("R's line meets the supports' lines too far away (or not at all) for Culmann's K and L. ")
        else:
            d.culmann(culmann[1:])
    d.senses()
    return d.record()


__all__ = ["free_body_analysis"]
