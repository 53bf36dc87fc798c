"""Contacts and loop closures between two bodies (thesis 9.3, 9.49-9.60).

A :class:`Contact` joins body ``a`` to body ``b`` (or the ground, ``b = -1``) *outside* the tree of
a :class:`planargeo.mechanics.model.Model`, closing a loop.  For the bodies' world poses it gives
the motion space ``z`` (the relative motions allowed, ``v_a - v_b = z θ̇``, 9.54), the reaction
space ``B`` (``zᵀB = 0``: contact forces ``F = B ξ`` are powerless, 9.59-9.60) and the position
residual the stabilised simulation drives to zero (:mod:`planargeo.simulate.loops`).  Sign
convention (Definition 42): contact ``k`` puts ``+1`` in column ``a`` and ``-1`` in column ``b`` of
``G``; in 9.61 the wrench ``-F`` acts on body ``a``, ``+F`` on ``b``.

Examples
--------
>>> c, pose = Contact("pin", 1, -1, point_b=(2.0, 0.0)), np.array([[0.0, 0.0, 0.0], [2.0, 0.0, 0.0]])
>>> z_of(c, pose)[:, 0], residual(c, pose)      # rotation about (2, 0): the point [0, -2, 1]; closed
(array([ 0., -2.,  1.]), array([0., 0.]))
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo._validate import as_array, as_scalar
from planargeo.errors import DegenerateGeometryError, InputError, ShapeError
from planargeo.geometry._docs import entries
from planargeo.mechanics.model import _check_name, _finite_tuple

__all__ = ["Contact", "CONTACT_DOFS", "contact_matrix", "validate_contacts", "world_point",
           "z_of", "B_of", "residual", "contact_bias", "stacked_contact_spaces"]

#: Number of relative degrees of freedom ``k`` each contact kind allows (columns of ``z``).
CONTACT_DOFS = {"pin": 1, "slider": 1, "weld": 0}

#: The parameters of the per-contact functions, described once (:func:`planargeo.geometry._docs.entries`).
_documented = entries({
    "contact": "contact : Contact\n    One contact.",
    "contacts": "contacts : sequence of Contact\n    The model's contacts (loop closures).",
    "n_bodies": "n_bodies : int\n    Number of bodies of the model.",
    "pose": "pose : array_like, shape (..., N, 3)\n    World poses ``(x, y, θ)`` of the N bodies (m, rad).",
})


@dataclass(frozen=True)
class Contact:
    """A contact / loop closure between body ``a`` and body ``b`` (frozen; thesis 9.3, Definition 42, 9.49).

    Parameters
    ----------
    kind : {"pin", "slider", "weld"}
        Pin (1 dof: rotation), slider (1 dof: translation) or weld (0 dof).
    a, b : int
        Body indices, the ``+1`` and ``-1`` columns of ``G`` (``b = -1``: the ground).
    point_a, point_b : (x, y)
        The contact point in body a's frame, and in body b's (the world's for the ground).
    direction : (dx, dy)
        Slider only: the sliding direction in body b's frame (non-zero).
    angle : float
        Slider and weld: the relative angle ``theta_a - theta_b`` kept by the contact.
    name : str
        A label for drawings and messages.

    Examples
    --------
    >>> Contact("slider", 2, -1, direction=(0.0, 1.0), angle=np.pi / 2).dofs
    1
    >>> Contact("glue", 0, -1)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: kind must be one of ['pin', 'slider', 'weld'], got 'glue'
    """

    kind: str
    a: int
    b: int = -1
    point_a: tuple[float, float] = (0.0, 0.0)
    point_b: tuple[float, float] = (0.0, 0.0)
    direction: tuple[float, float] = (1.0, 0.0)
    angle: float = 0.0
    name: str = ""

    def __post_init__(self):
        if not isinstance(self.kind, str) or self.kind not in CONTACT_DOFS:
            raise InputError(f"kind must be one of {list(CONTACT_DOFS)}, got {self.kind!r}")
        for nm in ("a", "b"):
            val = getattr(self, nm)
            if isinstance(val, bool) or not isinstance(val, (int, np.integer)):
                raise InputError(f"{nm} must be an integer body index, got {val!r}")
            object.__setattr__(self, nm, int(val))
        if self.a < 0:
            raise InputError(f"a must be a body index >= 0, got {self.a}")
        if self.b < -1:
            raise InputError(f"b must be a body index >= 0 or -1 (ground), got {self.b}")
        if self.a == self.b:
            raise InputError(f"a and b must be different bodies, got a = b = {self.a}")
        object.__setattr__(self, "point_a", _finite_tuple(self.point_a, "point_a", 2))
        object.__setattr__(self, "point_b", _finite_tuple(self.point_b, "point_b", 2))
        d = _finite_tuple(self.direction, "direction", 2)
        if self.kind == "slider" and d == (0.0, 0.0):
            raise DegenerateGeometryError("direction must be non-zero for a slider contact, got (0, 0)")
        n = float(np.hypot(*d)) or 1.0
        object.__setattr__(self, "direction", (d[0] / n, d[1] / n))
        object.__setattr__(self, "angle", as_scalar(self.angle, "angle"))
        _check_name(self.name)

    @property
    def dofs(self) -> int:
        """Relative degrees of freedom ``k`` (columns of ``z``)."""
        return CONTACT_DOFS[self.kind]

    @property
    def nc(self) -> int:
        """Number of constraints ``3 - k`` (columns of ``B``)."""
        return 3 - self.dofs


@_documented
def validate_contacts(contacts, n_bodies: int) -> tuple[Contact, ...]:
    """Check ``contacts`` against a model of ``n_bodies`` bodies; return them as a tuple (the rows of ``G``, 9.49).

    {parameters contacts n_bodies}

    Returns
    -------
    tuple of Contact

    Raises
    ------
    InputError
        For an entry that is not a Contact or names a body out of range.

    Examples
    --------
    >>> validate_contacts([Contact("pin", 3, -1)], 2)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: contacts[0].a must be a body index in 0..1, got 3
    """
    out = tuple(contacts)
    for k, c in enumerate(out):
        if not isinstance(c, Contact):
            raise InputError(f"contacts[{k}] must be a Contact, got {type(c).__name__}")
        if c.a >= n_bodies:
            raise InputError(f"contacts[{k}].a must be a body index in 0..{n_bodies - 1}, got {c.a}")
        if c.b >= n_bodies:
            raise InputError(f"contacts[{k}].b must be -1 or a body index in 0..{n_bodies - 1}, got {c.b}")
    return out


@_documented
def contact_matrix(contacts, n_bodies: int) -> np.ndarray:
    """The ``m × n`` contact matrix ``G``: row ``k`` ``+1`` at body ``a``, ``-1`` at ``b`` (Definition 42, 9.49).

    {parameters contacts n_bodies}

    Returns
    -------
    numpy.ndarray, shape (m, n_bodies)

    Examples
    --------
    >>> contact_matrix([Contact("pin", 3, 6), Contact("pin", 7, 8)], 9).astype(int)   # Fig 9.2
    array([[ 0,  0,  0,  1,  0,  0, -1,  0,  0],
           [ 0,  0,  0,  0,  0,  0,  0,  1, -1]])
    """
    cs = validate_contacts(contacts, n_bodies)
    G = np.zeros((len(cs), n_bodies))
    for k, c in enumerate(cs):
        G[k, c.a] = 1.0
        if c.b >= 0:
            G[k, c.b] = -1.0
    return G


def _pose_of(pose, i):
    if i < 0:
        return 0.0, 0.0, 0.0
    return pose[..., i, 0], pose[..., i, 1], pose[..., i, 2]


@_documented
def world_point(pose, body: int, point) -> np.ndarray:
    """World coordinates of ``point`` given in ``body``'s frame (``body = -1``: world; the pose of 2.1-2.9).

    {parameters pose}
    body : int
        Body index, or ``-1`` for the world frame.
    point : array_like, shape (2,)
        The point in the body's frame (m).

    Returns
    -------
    numpy.ndarray, shape (..., 2)

    Examples
    --------
    >>> world_point(np.array([[1.0, 0.0, np.pi / 2]]), 0, (1.0, 0.0)).round(12)
    array([1., 1.])
    """
    x, y, th = _pose_of(np.asarray(pose, dtype=float), body)
    c, s = np.cos(th), np.sin(th)
    px, py = point
    return np.stack(np.broadcast_arrays(x + c * px - s * py, y + s * px + c * py), -1)


def _pose(pose, contact=None):
    """``pose`` checked as (..., N, 3), and ``contact`` (if given) as a Contact between its bodies."""
    p = as_array(pose, "pose")
    if p.ndim < 2 or p.shape[-1] != 3:
        raise ShapeError(f"pose must have shape (..., N, 3), got shape {p.shape}")
    if contact is not None and not isinstance(contact, Contact):
        raise InputError(f"contact must be a Contact, got {type(contact).__name__}")
    n = p.shape[-2]
    if contact is not None and (contact.a >= n or contact.b >= n):
        raise InputError(f"contact refers to body {max(contact.a, contact.b)} but pose has {n} bodies")
    return p


def _slider_dir(contact, pose):
    thb = _pose_of(pose, contact.b)[2]
    c, s = np.cos(thb), np.sin(thb)
    dx, dy = contact.direction
    return c * dx - s * dy, s * dx + c * dy


@_documented
def z_of(contact: Contact, pose) -> np.ndarray:
    """Contact motion space ``z`` (3×k unit twists at the origin; thesis 9.54, 9.83).

    Pin: the rotation ``[y, -x, 1]`` about the world contact point (on body a); slider: the
    translation along the world sliding direction; weld: an empty (3, 0) array.

    {parameters contact pose}

    Returns
    -------
    numpy.ndarray, shape (..., 3, k)

    Examples
    --------
    >>> c = Contact("slider", 0, -1, direction=(0.0, 1.0), angle=np.pi / 2)
    >>> z_of(c, np.array([[0.0, 5.925, np.pi / 2]]))     # thesis 9.83
    array([[0.],
           [1.],
           [0.]])
    """
    pose = _pose(pose, contact)
    shape = pose.shape[:-2]
    if contact.kind == "pin":
        P = world_point(pose, contact.a, contact.point_a)
        z = np.stack([P[..., 1], -P[..., 0], np.ones(shape)], -1)[..., None]
    elif contact.kind == "slider":
        dx, dy = _slider_dir(contact, pose)
        z = np.stack(np.broadcast_arrays(dx, dy, np.zeros(shape)), -1)[..., None]
    else:
        z = np.zeros(shape + (3, 0))
    return z


@_documented
def B_of(contact: Contact, pose) -> np.ndarray:
    """Contact reaction space ``B`` (3×(3-k) wrenches at the origin, ``z^T B = 0``; 9.59-9.60, 9.87).

    Pin: unit forces along x and y through the contact point; slider: the unit force normal
    to the slide through the point on body a, and the unit couple; weld: the identity.  As
    for joints (:func:`planargeo.mechanics.joints.reaction_space`), except that a contact's
    slider normal is the direction turned by **-90°** (a joint's by +90°, 5.63), as printed in
    9.87, so that ``ξ`` compares directly with 9.90.

    {parameters contact pose}

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3-k)

    Examples
    --------
    >>> c = Contact("slider", 0, -1, point_a=(0.5, 0.0), direction=(0.0, 1.0), angle=np.pi / 2)
    >>> B_of(c, np.array([[0.0, 5.425, np.pi / 2]])).round(12)   # thesis 9.87
    array([[ 1.   ,  0.   ],
           [ 0.   ,  0.   ],
           [-5.925,  1.   ]])
    """
    pose = _pose(pose, contact)
    shape = pose.shape[:-2]
    one, zero = np.ones(shape), np.zeros(shape)
    P = world_point(pose, contact.a, contact.point_a)
    px, py = P[..., 0], P[..., 1]
    if contact.kind == "pin":
        B = np.stack([np.stack([one, zero, -py], -1), np.stack([zero, one, px], -1)], -1)
    elif contact.kind == "slider":
        dx, dy = _slider_dir(contact, pose)
        nx, ny = dy + zero, -dx + zero
        B = np.stack([np.stack([nx, ny, px * ny - py * nx], -1), np.stack([zero, zero, one], -1)], -1)
    else:
        B = np.broadcast_to(np.eye(3), shape + (3, 3)).copy()
    return B


@_documented
def residual(contact: Contact, pose) -> np.ndarray:
    """Position-level loop-closure residual, zero when the loop is closed (position form of 9.59-9.60).

    Pin: world ``point_a - point_b``; slider: ``point_a``'s signed distance from the sliding line
    and the relative-angle error; weld: the point difference and the angle error (wrapped to
    ``(-π, π]``).

    {parameters contact pose}

    Returns
    -------
    numpy.ndarray, shape (..., 3-k)
        Closure errors (m, rad).

    Examples
    --------
    >>> residual(Contact("slider", 0, -1, direction=(0.0, 1.0)), np.array([[0.25, 3.0, 0.1]]))
    array([0.25, 0.1 ])
    """
    pose = _pose(pose, contact)
    Pa = world_point(pose, contact.a, contact.point_a)
    Pb = world_point(pose, contact.b, contact.point_b)
    dP = Pa - Pb
    dth = _pose_of(pose, contact.a)[2] - (_pose_of(pose, contact.b)[2] if contact.b >= 0 else 0.0) - contact.angle
    dth = np.asarray(np.angle(np.exp(1j * np.asarray(dth))))
    if contact.kind == "pin":
        return dP
    if contact.kind == "slider":
        dx, dy = _slider_dir(contact, pose)
        # normal n = (dy, -dx): the sliding direction turned by -90 degrees
        return np.stack(np.broadcast_arrays(dP[..., 0] * dy - dP[..., 1] * dx, dth), -1)
    return np.concatenate([dP, dth[..., None]], -1)


def contact_bias(v_a, v_b) -> np.ndarray:
    """Contact bias acceleration ``ν = v_a × (v_a - v_b)`` (thesis 9.55, 9.5 step 3).

    With ``z θ̇ = v_a - v_b`` (9.54) it equals ``v_b × (v_a - v_b)``: either body may carry ``z``.

    Parameters
    ----------
    v_a, v_b : array_like, shape (..., 3)
        World twists of the contact's two bodies (zero for the ground).

    Returns
    -------
    numpy.ndarray, shape (..., 3)

    Examples
    --------
    >>> contact_bias([0.0, 0.0, 2.0], [0.0, 0.0, 0.0])   # a pin at the origin: no bias
    array([0., 0., 0.])
    """
    from planargeo.screws.twists import crm

    va = as_array(v_a, "v_a", (3,))
    vb = as_array(v_b, "v_b", (3,))
    return np.einsum("...ij,...j->...i", crm(va), va - vb)


@_documented
def stacked_contact_spaces(contacts, pose):
    """Block-diagonal ``z = {{z_k}}`` (3m×Σk) and ``B = {{B_k}}`` (3m×Σ(3-k)) for all contacts (thesis 9.54, 9.60).

    {parameters contacts pose}

    Returns
    -------
    tuple of numpy.ndarray
        ``(z, B)``, shapes (3m, Σk) and (3m, Σ(3-k)).

    Raises
    ------
    ShapeError
        If ``pose`` is not ``(N, 3)``.

    Examples
    --------
    >>> z, B = stacked_contact_spaces([Contact("pin", 0, -1), Contact("weld", 0, -1)], np.zeros((1, 3)))
    >>> z.shape, B.shape
    ((6, 1), (6, 5))
    """
    pose = _pose(pose)
    cs = validate_contacts(contacts, pose.shape[-2])
    if pose.ndim != 2:
        raise ShapeError(f"pose must have shape (N, 3) here, got shape {pose.shape}")
    m = len(cs)
    kz = sum(c.dofs for c in cs)
    kb = sum(c.nc for c in cs)
    z = np.zeros((3 * m, kz))
    B = np.zeros((3 * m, kb))
    iz = ib = 0
    for k, c in enumerate(cs):
        z[3 * k:3 * k + 3, iz:iz + c.dofs] = z_of(c, pose)
        B[3 * k:3 * k + 3, ib:ib + c.nc] = B_of(c, pose)
        iz += c.dofs
        ib += c.nc
    return z, B
