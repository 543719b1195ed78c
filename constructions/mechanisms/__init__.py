"""Linkages: the model apart from how it is put together.

The model (:mod:`.model`: links, sliding joints, points fixed to links, branches, mobility); the assembly
plan, crank then dyads (:mod:`.assembly`); the construction of the space diagram at one crank angle
(:mod:`.pose`); the bodies and the joints that carry forces between them (:mod:`.topology`); what kind of
four-bar it is (:mod:`.classify`); instant centres by Kennedy's theorem (:mod:`.centres`,
:mod:`.instant_centres`, the drawing in :mod:`.centre_diagram`); the cycle as charts and coupler curves
(:mod:`.cycle`); and the independent check of any 1-DoF mechanism by constraint equations in body
coordinates (:mod:`.constraint_model`, :mod:`.constraint_equations`, :mod:`.constraint_kinematics`).
"""
