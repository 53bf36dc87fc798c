"""Drawing: twists as points, wrenches as lines, inertias as conics (matplotlib).

Math modules never import matplotlib; this package imports the math.
"""
from .artists import (ConicArtist, LineArtist, PointArtist, plot_conic, plot_inertia,  # noqa: F401
                      plot_line, plot_point)
from .style import COLORS, OKABE_ITO, rc_context, style  # noqa: F401
