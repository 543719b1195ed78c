"""Gears: involute spur-gear geometry (:mod:`.tooth`), a pair in mesh with its contact geometry
(:mod:`.mesh`, checked by :mod:`.mesh_check`), the interference limits (:mod:`.interference`) and gear
trains, ordinary and planetary (:mod:`.trains`, checked by :mod:`.train_check`)."""
