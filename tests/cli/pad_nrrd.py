#!/usr/bin/python3
"""Writes a copy of a raw NRRD volume padded by one layer of samples on every side.

Usage: pad_nrrd.py IN.nrrd ISO OUT.nrrd

The pad value is the volume's smallest sample when it is below ISO, else the
largest whole number at least one below ISO: the rule isotrack's --cap follows
(core's capPadValue), written here independently with numpy for the CLI test
that compares the two. The copy has no origin field (origin 0): it sits one
spacing off the original, which the test's comparisons do not see (triangle
counts, enclosed volume and area).
"""
import math
import sys

import numpy as np

TYPES = {"short": "<i2", "int16": "<i2", "ushort": "<u2", "uint16": "<u2", "float": "<f4", "uchar": "u1",
         "unsigned char": "u1", "int": "<i4", "double": "<f8"}


def read_nrrd(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"\n\n")
    fields = {}
    for line in data[:end].decode("latin-1").splitlines()[1:]:
        if line.startswith("#") or ":" not in line:
            continue
        key, value = line.split(":", 1)
        fields[key.strip()] = value.strip()
    if fields.get("encoding") != "raw":
        raise SystemExit(f"{path}: encoding {fields.get('encoding')} (this script reads raw only)")
    sizes = [int(s) for s in fields["sizes"].split()]
    dtype = np.dtype(TYPES[fields["type"]])
    samples = np.frombuffer(data, dtype=dtype, count=int(np.prod(sizes)), offset=end + 2)
    return fields, samples.reshape(sizes[::-1])  # z, y, x


def main():
    source, iso, target = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    fields, volume = read_nrrd(source)
    lowest = volume.min()
    pad = lowest if lowest < iso else math.floor(iso - 1)
    padded = np.pad(volume, 1, mode="constant", constant_values=pad)
    header = ["NRRD0004", f"type: {fields['type']}", "dimension: 3",
              "sizes: " + " ".join(str(s) for s in padded.shape[::-1]), f"spacings: {fields['spacings']}",
              "encoding: raw", "endian: little"]
    with open(target, "wb") as f:
        f.write(("\n".join(header) + "\n\n").encode())
        f.write(padded.astype(volume.dtype.newbyteorder("<")).tobytes())


if __name__ == "__main__":
    main()
