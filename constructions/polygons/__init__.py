"""Vector polygons drawn step by step: shared machinery (:mod:`.common`), the velocity polygon
(:mod:`.velocity`) and the acceleration polygon (:mod:`.acceleration`)."""
