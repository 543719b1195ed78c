"""The step that writes the angle of action, the pitch-line speed and the sliding at the tips
(:mod:`constructions.gears.action`) under the contact ratio, as the notes work them."""

from __future__ import annotations

from ..record import Construction, StepKind, Value
from .action import Action
from .contact import Pair


def action_step(rec: Construction, pair: Pair, act: Action) -> Construction:
    vals = {"d1": Value("angle", act.angle_of_action[0])}
    words = ("Angle of action (arc of action AB / cos \u03c6' over the pitch radius r' = r_b / cos \u03c6', so AB / r_b; "
             "C.R. x 360\u00b0/N): gear 1 $d1")
    if act.angle_of_action[1] is not None:
        vals["d2"] = Value("angle", act.angle_of_action[1])
        words += ", gear 2 $d2"
    words += "."
    if act.omega is not None:
        vals |= {"w1": Value("angular velocity", act.omega[0]), "w2": Value("angular velocity", act.omega[1]),
                 "vp": Value("velocity", act.pitch_line_speed), "va": Value("velocity", act.sliding_start),
                 "vb": Value("velocity", act.sliding_end)}
        rel = "\u03c9\u2081" if pair.rack else "(\u03c9\u2081 - \u03c9\u2082)" if pair.internal else "(\u03c9\u2081 + \u03c9\u2082)"
        words += (f" Pinion at $w1{'' if pair.rack else ', gear 2 at $w2'}: pitch-line speed V = \u03c9\u2081 r\u2081' = $vp; "
                  f"sliding velocity = {rel} x the distance from P along the line of action: at A, contact "
                  f"starts, $va; at B, contact ends, $vb.")
    return rec.then(words, values=vals, kind=StepKind.ANSWER)
