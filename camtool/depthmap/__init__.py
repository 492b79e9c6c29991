"""Depth images in and circle-of-confusion maps out: OpenEXR, 16-bit PNG and TIFF, NumPy ``.npy``.

The file formats live here and nowhere else; the optional packages they need (the ``depth`` extra: OpenEXR,
imageio, tifffile) are imported only when such a file is read or written.
"""
