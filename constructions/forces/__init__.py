"""Static and D'Alembert force analysis of linkages: the effects a scene declares (:mod:`.effects`), the
bodies and the joints that carry forces between them (:mod:`.bodies`), the graphical construction --
free bodies, two- and three-force members, force polygons dyad by dyad (:mod:`.polygon`) -- and the
independent checks: the global equilibrium system and virtual work (:mod:`.equilibrium`)."""
