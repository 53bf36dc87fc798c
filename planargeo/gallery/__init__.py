"""The thesis's planar figures, redrawn from the package's own numbers.

* :mod:`planargeo.gallery.figures` -- one module per chapter, each figure a function;
* :mod:`planargeo.gallery.build` -- ``planargeo gallery``: writes (or ``--check``\\ s) ``gallery/*.svg``.
"""
