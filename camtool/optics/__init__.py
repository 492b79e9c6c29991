"""Optical models beyond the thin lens: prescriptions, first-order optics, thick lens, real rays.

Submodules (import what you need; numpy is imported only by :mod:`raytrace`):

- :mod:`camtool.optics.prescription` -- validated lens prescriptions;
- :mod:`camtool.optics.paraxial` -- y–nu trace, first-order data, the ``paraxial`` model;
- :mod:`camtool.dof.thick` -- the ``thick`` closed form (pupil magnification, hiatus);
- :mod:`camtool.optics.raytrace` -- real rays by Snell's law, the ``raytrace`` model.
"""
