"""The effects a scene declares, and nothing else: external forces and couples, masses with their
centres of gravity and moments of inertia, gravity (only when g is set), springs, and Coulomb friction
at sliders (only where mu is set).  All SI: N, N m (CCW positive), kg, kg m^2, m/s^2, N/m, m.

A body is a link or a slider block, by its number; a point is a joint or an attached point of that body
(for a block, its joint).  The centre of gravity of a link is one of its points (a scene that gives it
by distance and angle adds it as an attached point, so the acceleration polygon finds its image)."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..geometry import Vec


@dataclass(frozen=True, slots=True)
class Load:
    """An external force ``force`` (N) on body ``body``, acting at its point ``at``; ``given`` says how the
    scene gave it when that was not as a force (a gas pressure on a bore: "p \u03c0 d\u00b2/4 with ...")."""

    name: str
    body: int
    at: str
    force: Vec
    given: str = ""


@dataclass(frozen=True, slots=True)
class Balance:
    """The inverse static problem: the load named ``load`` -- its line and direction given, its force a
    unit vector along them -- has the magnitude that needs the driving torque ``torque`` (N m, CCW positive)
    on the crank (:mod:`.inverse`)."""

    load: str
    torque: float


@dataclass(frozen=True, slots=True)
class Couple:
    """An external couple ``torque`` (N m, CCW positive) on body ``body``."""

    name: str
    body: int
    torque: float


@dataclass(frozen=True, slots=True)
class Mass:
    """The mass ``mass`` (kg) of body ``body``, its centre of gravity at its point ``centre`` and its moment
    of inertia ``inertia`` (kg m^2) about that centre."""

    body: int
    mass: float
    centre: str
    inertia: float = 0.0


@dataclass(frozen=True, slots=True)
class End:
    """One end of a spring: point ``at`` of body ``body`` (None: the frame, ``at`` a fixed point)."""

    body: int | None
    at: str


@dataclass(frozen=True, slots=True)
class Spring:
    """A linear spring between two ends: tension k (L - L0) pulls them together (negative: pushes)."""

    name: str
    a: End
    b: End
    stiffness: float
    free_length: float

    def pull(self, a: Vec, b: Vec) -> Vec:
        """The spring's force on end ``a`` when its ends stand at ``a`` and ``b``: the tension k (L - L0)
        towards ``b`` (end b feels the opposite); none when the ends coincide (no line to act along)."""
        d = b - a
        length = d.norm()
        if length == 0.0:
            return Vec(0.0, 0.0)
        # the direction first: k (L - L0) / L overflows when the ends stand a subnormal distance apart
        return Vec(d.x / length, d.y / length) * (self.stiffness * (length - self.free_length))


@dataclass(frozen=True)
class Effects:
    """Everything that loads a mechanism.  ``gravity`` is the acceleration of gravity as a vector (None:
    no weights); ``friction`` maps a slider block (or a pin in a slot, by its joint name) to its mu;
    ``fixed`` names the fixed points springs may be anchored to, with their positions; ``balance`` is the
    load to be found for a given driving torque (None: every load is given)."""

    loads: tuple[Load, ...] = ()
    couples: tuple[Couple, ...] = ()
    masses: tuple[Mass, ...] = ()
    springs: tuple[Spring, ...] = ()
    gravity: Vec | None = None
    friction: dict[int | str, float] = field(default_factory=dict)
    fixed: dict[str, Vec] = field(default_factory=dict)
    balance: Balance | None = None

    @property
    def inertial(self) -> bool:
        """True when some body has mass: then the analysis is dynamic (D'Alembert) and needs the
        accelerations; without masses it is static and needs none."""
        return bool(self.masses)

    @property
    def empty(self) -> bool:
        return not (self.loads or self.couples or self.masses or self.springs)

    def mass_of(self, body: int) -> Mass | None:
        return next((x for x in self.masses if x.body == body), None)


NO_EFFECTS = Effects()
