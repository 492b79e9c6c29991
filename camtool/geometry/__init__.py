"""Imaging geometry of a thin lens: focusing, field of view, circle of confusion, composition."""
