"""Static and D'Alembert force analysis: the effects a scene declares (:mod:`.effects`, :mod:`.inertia`),
the bodies and the joints that carry forces between them (:mod:`.bodies`), the graphical construction --
the drawing state shared by every polygon (:mod:`.board`), the dyads and the crank (:mod:`.dyads`: two-
and three-force members, guides; :mod:`.slotted`: slots and two lines; :mod:`.friction`; :mod:`.crank`)
run from the output back to the crank with free bodies and records (:mod:`.polygon`) -- a single rigid
body on supports (:mod:`.rigid_body`) by Culmann's method (:mod:`.free_body`, drawn with
:mod:`.free_body_drawing`), and the independent checks: the global equilibrium system and virtual work
(:mod:`.equilibrium`), the body's three equations (:mod:`.free_body_check`)."""
