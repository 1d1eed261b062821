#!/usr/bin/python3
"""ct_to_dicom.py -- the CT sample written as a DICOM series, for testing isotrack's DICOM reader.

Usage: /usr/bin/python3 scripts/ct_to_dicom.py NHDR OUT_DIR [--shuffle SEED] [--second-series] [--dicomdir]

  NHDR             a detached NRRD header of raw little-endian int16 samples without "space
                   directions" (scripts/get_ct.sh writes assets/ct/cranium.nhdr)
  OUT_DIR          made if missing; gets one CT Image Storage file per slice (explicit VR
                   little endian)
  --shuffle SEED   random file names, written in random order, so that nothing about the
                   files' order tells the slices' order
  --second-series  also writes a small 64 x 64 x 4 series (another SeriesInstanceUID) into
                   the same folder, as a scanner's localizer would be
  --dicomdir       writes the series through pydicom's FileSet: files in its own folders
                   and a DICOMDIR listing them

The slices sit at ImagePositionPatient (0, 0, k * spacing_z) with an identity
ImageOrientationPatient, so the series describes the NRRD exactly (origin 0,
LPS identity). Samples are stored unsigned with RescaleIntercept = the smallest
sample, so that a reader must apply it; SliceThickness is deliberately not the
slice spacing, so that a reader trusting it fails. Needs Debian's python3-pydicom
and python3-numpy.
"""
import argparse
import os
import random

import numpy as np
import pydicom
from pydicom.dataset import Dataset, FileMetaDataset
from pydicom.uid import ExplicitVRLittleEndian, generate_uid

CT_IMAGE_STORAGE = "1.2.840.10008.5.1.4.1.1.2"


def read_nhdr(path):
    fields = {}
    with open(path, encoding="ascii") as f:
        for line in f:
            line = line.rstrip("\n")
            if ": " in line and not line.startswith("#"):
                key, value = line.split(": ", 1)
                fields[key] = value.strip()
    if fields.get("type") != "short" or fields.get("endian") != "little" or fields.get("encoding") != "raw":
        raise SystemExit("ct_to_dicom: %s: expected raw little-endian short data" % path)
    if "space directions" in fields or "space origin" in fields:
        raise SystemExit("ct_to_dicom: %s: expected no space directions or origin" % path)
    nx, ny, nz = (int(s) for s in fields["sizes"].split())
    spacings = fields["spacings"].split()
    data = os.path.join(os.path.dirname(path), fields["data file"])
    samples = np.fromfile(data, dtype="<i2")
    if samples.size != nx * ny * nz:
        raise SystemExit("ct_to_dicom: %s holds %d samples, not %d" % (data, samples.size, nx * ny * nz))
    return samples.reshape(nz, ny, nx), spacings


def slice_dataset(pixels, index, spacings, series_uid, study_uid, number, description, low, bits_stored):
    """One slice; spacings are the NRRD's text, so DS values read back as the same doubles."""
    meta = FileMetaDataset()
    meta.MediaStorageSOPClassUID = CT_IMAGE_STORAGE
    meta.MediaStorageSOPInstanceUID = generate_uid(entropy_srcs=[series_uid, str(index)])
    meta.TransferSyntaxUID = ExplicitVRLittleEndian
    ds = Dataset()
    ds.file_meta = meta
    ds.is_little_endian = True
    ds.is_implicit_VR = False
    ds.SOPClassUID = CT_IMAGE_STORAGE
    ds.SOPInstanceUID = meta.MediaStorageSOPInstanceUID
    ds.PatientName = "Cranium^Sample"
    ds.PatientID = "isotrack-ct"
    ds.StudyInstanceUID = study_uid
    ds.SeriesInstanceUID = series_uid
    ds.StudyID = "1"
    ds.StudyDate = "20000101"
    ds.StudyTime = "000000"
    ds.SeriesNumber = number
    ds.InstanceNumber = index + 1
    ds.Modality = "CT"
    ds.SeriesDescription = description
    ds.FrameOfReferenceUID = generate_uid(entropy_srcs=[study_uid, "frame"])
    ds.ImageOrientationPatient = [1, 0, 0, 0, 1, 0]
    z = float(spacings[2]) * index
    ds.ImagePositionPatient = [0, 0, repr(z) if z != int(z) else int(z)]
    ds.PixelSpacing = [spacings[1], spacings[0]]  # between rows (y), between columns (x)
    ds.SliceThickness = "2.5"  # not the spacing between slices, on purpose
    ds.RescaleIntercept = str(low)
    ds.RescaleSlope = "1"
    ds.Rows, ds.Columns = pixels.shape
    ds.SamplesPerPixel = 1
    ds.PhotometricInterpretation = "MONOCHROME2"
    ds.BitsAllocated = 16
    ds.BitsStored = bits_stored
    ds.HighBit = bits_stored - 1
    ds.PixelRepresentation = 0
    ds.PixelData = (pixels.astype(np.int32) - low).astype("<u2").tobytes()
    return ds


def series(volume, spacings, study_uid, number, description):
    series_uid = generate_uid(entropy_srcs=[study_uid, str(number)])
    # One rescale for the whole series, from its smallest sample.
    low = min(int(volume.min()), 0)
    bits_stored = max(1, int(volume.max() - low).bit_length())
    out = []
    for k in range(volume.shape[0]):
        out.append(slice_dataset(volume[k], k, spacings, series_uid, study_uid, number, description, low, bits_stored))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("nhdr")
    parser.add_argument("out")
    parser.add_argument("--shuffle", type=int)
    parser.add_argument("--second-series", action="store_true")
    parser.add_argument("--dicomdir", action="store_true")
    args = parser.parse_args()

    volume, spacings = read_nhdr(args.nhdr)
    study_uid = generate_uid(entropy_srcs=["isotrack cranium study"])
    datasets = series(volume, spacings, study_uid, 1, "cranium")
    if args.second_series:
        small = volume[::27, ::4, ::4][:4]
        coarse = [repr(float(spacings[0]) * 4), repr(float(spacings[1]) * 4), repr(float(spacings[2]) * 27)]
        datasets += series(small, coarse, study_uid, 2, "localizer")

    os.makedirs(args.out, exist_ok=True)
    if args.dicomdir:
        from pydicom.fileset import FileSet
        fileset = FileSet()
        for ds in datasets:
            fileset.add(ds)
        fileset.write(args.out)
        print(os.path.join(args.out, "DICOMDIR"))
        return
    order = list(range(len(datasets)))
    names = ["slice_%04d.dcm" % k for k in order]
    if args.shuffle is not None:
        rng = random.Random(args.shuffle)
        rng.shuffle(order)
        names = ["%08x.dcm" % rng.getrandbits(32) for _ in order]
    for name, k in zip(names, order):
        pydicom.dcmwrite(os.path.join(args.out, name), datasets[k], write_like_original=False)
    print(args.out)


if __name__ == "__main__":
    main()
