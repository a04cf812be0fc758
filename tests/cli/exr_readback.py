#!/usr/bin/python3
"""tests/cli/exr_readback.py EXR PFM — the samples of an EXR the library wrote, as an
independent reader decodes them (OpenImageIO, Debian's python3-openimageio), against the PFM
the library wrote from the same floats (parsed here): equal bit for bit, NaN payloads too, or
exit 1 naming the first sample that differs. Run with Debian's /usr/bin/python3 (the module
is installed for it). PFM: header "Pf"/"PF", "W H", scale (< 0: little-endian), rows from the
bottom, channels interleaved."""
import struct, sys

import numpy as np
import OpenImageIO as oiio


def read_exr(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        sys.exit('exr_readback: OpenImageIO cannot open %s: %s' % (path, oiio.geterror()))
    spec = image.spec()
    pixels = image.read_image(oiio.FLOAT)
    image.close()
    if pixels is None:
        sys.exit('exr_readback: OpenImageIO cannot read the pixels of %s' % path)
    pixels = np.ascontiguousarray(pixels, dtype=np.float32).reshape(
        spec.height, spec.width, spec.nchannels)
    return spec, pixels.view(np.uint32)


def read_pfm(path):
    data = open(path, 'rb').read()
    parts, at = [], 0
    while len(parts) < 4:
        while data[at:at + 1].isspace():
            at += 1
        end = at
        while not data[end:end + 1].isspace():
            end += 1
        parts.append(data[at:end].decode('ascii'))
        at = end
    at += 1
    c = 3 if parts[0] == 'PF' else 1
    w, h = int(parts[1]), int(parts[2])
    order = '<' if float(parts[3]) < 0 else '>'
    rows = np.frombuffer(data[at:at + 4 * w * h * c], dtype=order + 'u4').reshape(h, w, c)
    return rows[::-1]  # top row first


def main():
    spec, exr = read_exr(sys.argv[1])
    pfm = read_pfm(sys.argv[2])
    if exr.shape != pfm.shape:
        sys.exit('exr_readback: %s is %s, %s %s' % (sys.argv[1], exr.shape, sys.argv[2],
                                                     pfm.shape))
    differ = np.argwhere(exr != pfm)
    if len(differ):
        y, x, c = differ[0]
        sys.exit('exr_readback: %s (%d, %d) channel %d read back as 0x%08x, written 0x%08x '
                 '(%d samples differ)' % (sys.argv[1], x, y, c, exr[y, x, c], pfm[y, x, c],
                                          len(differ)))
    print('exr_readback: %s: %d x %d x %d samples (%s) equal bit for bit' % (
        sys.argv[1], spec.width, spec.height, spec.nchannels,
        spec.get_string_attribute('compression')))


main()
