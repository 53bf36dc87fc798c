"""Future-work figures (thesis 10.2.2): the truncated articulated recursion converging along a chain."""
from __future__ import annotations

import numpy as np

from planargeo.algorithms.articulated_inertia import articulated_inertia
from planargeo.draw.charts import plot_curves
from planargeo.gallery.figures import register
from planargeo.scenes.horizontal_chain import effective_centre, horizontal_chain_model

#: bodies of the chain and the recursion steps shown
N_BODIES = 9
STEPS = np.arange(0, N_BODIES)


def truncated_effective_quantities(lam: float, n: int = N_BODIES) -> np.ndarray:
    """``(d/L, m_y/m, A_z/(m ρ²))`` of the first body of the horizontal chain of 7.3 after ``k`` steps.

    Parameters
    ----------
    lam : float
        Size ratio ``λ = L/ρ``.
    n : int

    Returns
    -------
    ndarray (n, 3)
        Row ``k``: the effective quantities (7.26) with ``k`` bodies outboard.

    Examples
    --------
    >>> truncated_effective_quantities(2.0, 3)[1:].round(6)        # lambda = 2: exact from one step
    array([[0.666667, 1.5     , 1.333333],
           [0.666667, 1.5     , 1.333333]])
    """
    model = horizontal_chain_model(n, 1.0, 1.0 / lam, 1.0)
    rho2 = 1.0 / lam**2
    out = []
    for k in range(n):
        d, _, my, Az = effective_centre(articulated_inertia(model, np.zeros(n), steps=k).A[0])
        out.append((d, my, Az / rho2))
    return np.array(out)


@register(10.22, height=2.4, margins=(0.16, 0.97, 0.18, 0.95))
def extra_truncated_recursion(ax):
    """Extra — 10.2.2, "three iterations are almost as precise as six": the effective centre d/L of
    the first body of the horizontal chain of 7.3 (9 bodies) against the number of recursion steps
    (bodies outboard kept by articulated_recursion(..., steps=k)) for several size ratios λ = L/ρ;
    at λ = 2 one step is exact (7.27), elsewhere the error shrinks geometrically."""
    lams = (1.0, 2.0, 3.46, 4.9, 8.0)
    ys = [truncated_effective_quantities(lam)[:, 0] for lam in lams]
    plot_curves(STEPS, ys, [f"λ = {lam:g}" for lam in lams], ax, xlabel="recursion steps k",
                ylabel="$d/L$ of body 1", legend=dict(ncol=3, loc="lower right", fontsize=6.5))
    ax.set_xticks(STEPS)
