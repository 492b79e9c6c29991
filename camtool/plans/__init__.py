"""Use cases: every decision a command makes, as plain functions with keyword arguments and named results.

Between the formula packages (``geometry``, ``optics``, ``dof``, ``exposure``), the
preset database and the EXIF reader below, and the command line and the Python API
above. A plan resolves equipment (sensor, CoC and where it came from, a lens's own
focal length and f-number), chooses the model, runs the formulas and returns rows of
numbers with their provenance; it never sees a click context, never prints and never
parses text. Its errors are :class:`camtool.core.errors.CamtoolError`, above all
``DomainError`` naming the quantity, the value and the valid range, which the command
line turns into one line naming the option the user typed.
"""
