"""camtool: depth of field, field of view, focusing and exposure for photographers.

The formula modules work in millimetres, degrees and seconds and accept either
plain floats (computed with :mod:`math`, no numpy import) or numpy arrays
(broadcast together).
"""

__version__ = "0.1.0"
