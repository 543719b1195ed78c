"""The tolerance of a cam's profile for machining (``drafting export``), apart from the sampling itself so that
the command line's parser reads its default without loading numpy and the engine."""

EXPORT_TOLERANCE = 1e-6
"""The chord tolerance of an export, relative to the cam's size, when the caller states none."""

EXPORT_TOLERANCE_RANGE = (1e-7, 0.1)
"""The tolerances an export accepts: the points grow as 1 / sqrt(tolerance), and 1e-7 samples the notes'
roller cam in 4-9 s on two cores (1e-8 took 41 s, 1e-10 did not end in 600 s); above 0.1 of the cam's size
a chord is no profile at all."""
