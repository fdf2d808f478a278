#!/usr/bin/env python3
"""Prints the mean red, green and blue (0-255) of a rectangle of the X screen, read with Xlib
through ctypes (no screenshot tool needed): screen_pixels.py X Y WIDTH HEIGHT, under $DISPLAY."""
import ctypes
import sys

x, y, width, height = (int(v) for v in sys.argv[1:5])
xlib = ctypes.cdll.LoadLibrary("libX11.so.6")
xlib.XOpenDisplay.restype = ctypes.c_void_p
xlib.XOpenDisplay.argtypes = [ctypes.c_char_p]
xlib.XDefaultRootWindow.restype = ctypes.c_ulong
xlib.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
xlib.XGetImage.restype = ctypes.c_void_p
xlib.XGetImage.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.c_int, ctypes.c_int, ctypes.c_uint, ctypes.c_uint,
                           ctypes.c_ulong, ctypes.c_int]
xlib.XGetPixel.restype = ctypes.c_ulong
xlib.XGetPixel.argtypes = [ctypes.c_void_p, ctypes.c_int, ctypes.c_int]

display = xlib.XOpenDisplay(None)
if not display:
    sys.exit("screen_pixels.py: cannot open the display")
z_pixmap = 2
image = xlib.XGetImage(display, xlib.XDefaultRootWindow(display), x, y, width, height, 0xFFFFFFFF, z_pixmap)
total = [0, 0, 0]
for j in range(height):
    for i in range(width):
        pixel = xlib.XGetPixel(image, i, j)  # 24-bit TrueColor: 0xRRGGBB
        total[0] += (pixel >> 16) & 0xFF
        total[1] += (pixel >> 8) & 0xFF
        total[2] += pixel & 0xFF
count = width * height
print(" ".join(str(round(t / count)) for t in total))
