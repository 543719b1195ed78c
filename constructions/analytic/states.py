"""What the closed forms return: frozen containers of read-only arrays over a set of crank angles."""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

__all__ = ["FOURBAR_FIELDS", "SLIDER_FIELDS", "FourBarState", "PointState", "SliderCrankState", "freeze"]


def freeze(obj) -> None:
    """Make every array field of the dataclass ``obj`` read-only."""
    for f in fields(obj):
        value = getattr(obj, f.name)
        if isinstance(value, np.ndarray):
            value.flags.writeable = False


@dataclass(frozen=True, eq=False)
class FourBarState:
    """Positions, velocities and accelerations of a four-bar O1-B-C-O2 over a set of crank angles.

    Attributes
    ----------
    Bx, By : ndarray
        Crank pin B (m).
    Cx, Cy : ndarray
        Coupler-rocker pin C (m).
    theta2 : ndarray
        Coupler angle, direction B -> C (rad, in (-pi, pi]).
    theta3 : ndarray
        Rocker angle, direction O2 -> C (rad, in (-pi, pi]).
    omega2, omega3 : ndarray
        Coupler and rocker angular velocities (rad/s, CCW positive).
    VBx, VBy, VCx, VCy : ndarray
        Absolute velocities of B and C (m/s).
    alpha2, alpha3 : ndarray
        Coupler and rocker angular accelerations (rad/s^2, CCW positive).
    ABx, ABy, ACx, ACy : ndarray
        Absolute accelerations of B and C (m/s^2).
    assembles : ndarray of bool
        True where the loop closes at this crank angle.
    condition : ndarray
        ``|sin|`` of the angle between coupler and rocker (the sine of the transmission angle);
        0 at a toggle, where the velocities and accelerations are NaN.
    """

    Bx: np.ndarray
    By: np.ndarray
    Cx: np.ndarray
    Cy: np.ndarray
    theta2: np.ndarray
    theta3: np.ndarray
    omega2: np.ndarray
    omega3: np.ndarray
    VBx: np.ndarray
    VBy: np.ndarray
    VCx: np.ndarray
    VCy: np.ndarray
    alpha2: np.ndarray
    alpha3: np.ndarray
    ABx: np.ndarray
    ABy: np.ndarray
    ACx: np.ndarray
    ACy: np.ndarray
    assembles: np.ndarray
    condition: np.ndarray

    def __post_init__(self) -> None:
        freeze(self)


@dataclass(frozen=True, eq=False)
class SliderCrankState:
    """Positions, velocities and accelerations of an (offset) slider-crank O1-B-C, C on a straight guide.

    Attributes
    ----------
    Bx, By : ndarray
        Crank pin B (m).
    Cx, Cy : ndarray
        Slider pin C (m), on the guide.
    theta2 : ndarray
        Coupler angle, direction B -> C (rad, in (-pi, pi]).
    omega2 : ndarray
        Coupler angular velocity (rad/s, CCW positive).
    VBx, VBy, VCx, VCy : ndarray
        Absolute velocities of B and C (m/s); V_C is parallel to the guide.
    slider_speed : ndarray
        Signed speed of C along the guide direction ``(cos guide_angle, sin guide_angle)`` (m/s).
    alpha2 : ndarray
        Coupler angular acceleration (rad/s^2, CCW positive).
    ABx, ABy, ACx, ACy : ndarray
        Absolute accelerations of B and C (m/s^2); A_C is parallel to the guide.
    slider_acceleration : ndarray
        Signed acceleration of C along the guide direction (m/s^2).
    assembles : ndarray of bool
        True where the coupler reaches the guide at this crank angle.
    condition : ndarray
        Sine of the angle between the two velocity trial lines (V_CB perpendicular to BC, V_C along
        the guide) ``= |unit(C - B) . e|``; 0 when the coupler is perpendicular to the guide.
    """

    Bx: np.ndarray
    By: np.ndarray
    Cx: np.ndarray
    Cy: np.ndarray
    theta2: np.ndarray
    omega2: np.ndarray
    VBx: np.ndarray
    VBy: np.ndarray
    VCx: np.ndarray
    VCy: np.ndarray
    slider_speed: np.ndarray
    alpha2: np.ndarray
    ABx: np.ndarray
    ABy: np.ndarray
    ACx: np.ndarray
    ACy: np.ndarray
    slider_acceleration: np.ndarray
    assembles: np.ndarray
    condition: np.ndarray

    def __post_init__(self) -> None:
        freeze(self)


@dataclass(frozen=True, eq=False)
class PointState:
    """Position, velocity and acceleration of a point D fixed to a link.

    Attributes
    ----------
    Dx, Dy : ndarray
        Position of D (m).
    VDx, VDy : ndarray
        Absolute velocity of D (m/s).
    ADx, ADy : ndarray
        Absolute acceleration of D (m/s^2); NaN when the base point's acceleration and the link's
        angular acceleration were not given.
    """

    Dx: np.ndarray
    Dy: np.ndarray
    VDx: np.ndarray
    VDy: np.ndarray
    ADx: np.ndarray
    ADy: np.ndarray

    def __post_init__(self) -> None:
        freeze(self)


def _array_fields(cls) -> tuple[str, ...]:
    return tuple(f.name for f in fields(cls) if f.name != "assembles")


#: The float fields of a :class:`FourBarState` and of a :class:`SliderCrankState`, in their order (every
#: field but the bool ``assembles``): a row each in a block of output buffers.
FOURBAR_FIELDS = _array_fields(FourBarState)
SLIDER_FIELDS = _array_fields(SliderCrankState)
