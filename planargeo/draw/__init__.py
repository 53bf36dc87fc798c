"""Drawing: twists as points, wrenches as lines, inertias as conics (matplotlib).

Math modules never import matplotlib; this package imports the math.  Every drawing
function takes what it draws first and ``ax=None`` next (None: the current axes).

* :mod:`~planargeo.draw.artists`: ``PointArtist``, ``LineArtist``, ``ConicArtist`` and
  ``plot_point`` / ``plot_line`` / ``plot_conic``;
* :mod:`~planargeo.draw.constructions`: the thesis's constructions (``draw_twist_sum``,
  ``draw_wrench_sum``, ``draw_polar_exterior``, ``draw_polar_interior``, ``draw_percussion``,
  ``draw_power``, the T/U decompositions of chapter 6: ``draw_decomposition``,
  ``draw_twist_split``, ``draw_wrench_split``, ``draw_projective_step`` ...);
* :mod:`~planargeo.draw.mechanism`: bodies, pins, sliders, ground, ``draw_model``,
  ``draw_joint_split``;
* :mod:`~planargeo.draw.charts`: curves over a parameter;
* :mod:`~planargeo.draw.layout`: views fitted to computed points;
* :mod:`~planargeo.draw.style`: the one visual language (Okabe-Ito roles, fixed rcParams,
  ``legend``).
"""
from planargeo.draw.artists import (ConicArtist, LineArtist, PointArtist, plot_conic, plot_line,  # noqa: F401
                      plot_point)
from planargeo.draw.constructions import (draw_decomposition, draw_percussion, draw_polar_exterior,  # noqa: F401
                            draw_polar_interior, draw_power, draw_projective_step,
                            draw_twist_split, draw_twist_sum, draw_wrench_split, draw_wrench_sum)
from planargeo.draw.mechanism import (draw_body, draw_ground, draw_joint_split, draw_link, draw_model,  # noqa: F401
                        draw_pin, draw_slider)
from planargeo.draw.style import COLORS, OKABE_ITO, rc_context, style  # noqa: F401
