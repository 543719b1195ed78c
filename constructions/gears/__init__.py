"""Gears: involute spur-gear geometry (:mod:`.tooth`), the flank a rack cutter leaves (:mod:`.flank`,
:mod:`.generation`), a pair in mesh with its contact geometry (:mod:`.contact`, drawn by :mod:`.mesh` and
:mod:`.thread`, checked by :mod:`.mesh_check`), the interference limits (:mod:`.interference`) and gear
trains, ordinary and planetary (:mod:`.trains`, drawn by :mod:`.train_drawing`, checked by
:mod:`.train_check`)."""
