"""Exported meshes land where tools users trust say the voxels are.

A ball centred on a voxel is written as NIfTI (by nibabel), as a DICOM series (by
pydicom) and as NRRD (its header written here, the header being the reference),
axis-aligned, flipped and oblique. `isotrack extract --frame lps|ras|voxel` exports
it, and the centre of the exported vertices (a ball centred on a grid point gives
a mesh symmetric about it) must be the reference's position of that voxel:
nibabel's affine (RAS) for NIfTI, the geometry pydicom reads back from the slices
(LPS) for DICOM, the header's space directions for NRRD. Nothing here calls
isotrack's own geometry code.

Usage: /usr/bin/python3 world_frames.py ISOTRACK WORK_DIR
"""
import os
import struct
import subprocess
import sys

import nibabel
import numpy as np
import pydicom
from pydicom.dataset import Dataset, FileMetaDataset
from pydicom.uid import CTImageStorage, ExplicitVRLittleEndian, generate_uid

ISOTRACK, WORK = sys.argv[1], sys.argv[2]
DIMS = (40, 48, 56)  # x, y, z
CENTRE = np.array([20.0, 30.0, 36.0])  # a voxel, in index (i, j, k)
TOLERANCE_MM = 1e-3
LPS_FROM_RAS = np.diag([-1.0, -1.0, 1.0, 1.0])
failures = []


def ball():
    """Indexed [i, j, k]: positive inside a radius-8 ball around CENTRE."""
    i, j, k = np.meshgrid(*(np.arange(n) for n in DIMS), indexing="ij")
    return (8.0 - np.sqrt((i - CENTRE[0]) ** 2 + (j - CENTRE[1]) ** 2 + (k - CENTRE[2]) ** 2)).astype(np.float32)


def rotation(degrees_z, degrees_x):
    cz, sz = np.cos(np.radians(degrees_z)), np.sin(np.radians(degrees_z))
    cx, sx = np.cos(np.radians(degrees_x)), np.sin(np.radians(degrees_x))
    return np.array([[1, 0, 0], [0, cx, -sx], [0, sx, cx]]) @ np.array([[cz, -sz, 0], [sz, cz, 0], [0, 0, 1]])


def affine(linear, origin):
    m = np.eye(4)
    m[:3, :3], m[:3, 3] = linear, origin
    return m


# (name, 4x4 index -> world affine in the file's own space)
CASES = [
    ("aligned", affine(np.diag([2.0, 2.0, 3.0]), [-64, -64, -96])),  # the most common NIfTI
    ("flipped", affine(np.diag([-0.9, 1.1, 1.3]), [40.5, -20.25, 7.0])),
    ("oblique", affine(rotation(30, 20) @ np.diag([0.8, 1.2, 1.5]), [-100.25, 55.5, 12.125])),
]


def read_ply_vertices(path):
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    count = next(int(line.split()[2]) for line in header if line.startswith("element vertex"))
    floats = np.frombuffer(data, dtype="<f4", count=count * 6, offset=end).reshape(count, 6)
    return floats[:, :3].astype(np.float64)


def mesh_centre(volume_path, frame, iso):
    out = os.path.join(WORK, "mesh.ply")
    if os.path.exists(out):
        os.remove(out)
    subprocess.run([ISOTRACK, "extract", "--volume", volume_path, "--iso", str(iso), "--frame", frame,
                    "--out", out], check=True, stdout=subprocess.DEVNULL)
    vertices = read_ply_vertices(out)
    if len(vertices) < 100:
        failures.append(f"{volume_path}: only {len(vertices)} vertices")
    return vertices.mean(axis=0)


def check(volume_path, iso, expected_lps, expected_index=CENTRE):
    """The ball's centre in LPS and in index space, as the reference tool places it."""
    expected = {"lps": expected_lps, "ras": expected_lps * [-1, -1, 1], "voxel": expected_index}
    for frame, want in expected.items():
        got = mesh_centre(volume_path, frame, iso)
        error = np.abs(got - want).max()
        status = "ok" if error <= TOLERANCE_MM else "FAIL"
        print(f"{status}: {os.path.basename(volume_path)} --frame {frame}: centre {np.round(got, 4)} "
              f"expected {np.round(want, 4)} (error {error:.2e})")
        if error > TOLERANCE_MM:
            failures.append(f"{volume_path} --frame {frame}: error {error}")


def nifti_case(name, ras_affine):
    path = os.path.join(WORK, f"{name}.nii")
    image = nibabel.Nifti1Image(ball(), ras_affine)
    image.set_sform(ras_affine, code=1)
    nibabel.save(image, path)
    reference = nibabel.load(path).affine  # what nibabel says, read back from the file
    check(path, 0.0, (LPS_FROM_RAS @ reference @ np.append(CENTRE, 1.0))[:3])


def dicom_case(name, lps_affine):
    """A CT series of int16 slices; one file per k, rows along j, columns along i."""
    folder = os.path.join(WORK, f"{name}_dicom")
    os.makedirs(folder, exist_ok=True)
    samples = np.round(ball() * 100).astype(np.int16)
    linear = lps_affine[:3, :3]
    spacing = np.linalg.norm(linear, axis=0)
    row_dir, col_dir = linear[:, 0] / spacing[0], linear[:, 1] / spacing[1]
    series, study, frame_of_reference = generate_uid(), generate_uid(), generate_uid()
    for k in range(DIMS[2]):
        meta = FileMetaDataset()
        meta.MediaStorageSOPClassUID = CTImageStorage
        meta.MediaStorageSOPInstanceUID = generate_uid()
        meta.TransferSyntaxUID = ExplicitVRLittleEndian
        ds = Dataset()
        ds.file_meta = meta
        ds.is_little_endian, ds.is_implicit_VR = True, False
        ds.SOPClassUID, ds.SOPInstanceUID = CTImageStorage, meta.MediaStorageSOPInstanceUID
        ds.Modality, ds.PatientName, ds.PatientID = "CT", "Frames^Test", "frames"
        ds.StudyInstanceUID, ds.SeriesInstanceUID, ds.FrameOfReferenceUID = study, series, frame_of_reference
        ds.SeriesNumber, ds.InstanceNumber = 1, k + 1
        ds.ImageOrientationPatient = [f"{v:.10f}" for v in (*row_dir, *col_dir)]
        ds.ImagePositionPatient = [f"{v:.10f}" for v in (lps_affine @ [0, 0, k, 1])[:3]]
        ds.PixelSpacing = [f"{spacing[1]:.10f}", f"{spacing[0]:.10f}"]  # between rows, between columns
        ds.SliceThickness = f"{spacing[2]:.10f}"
        ds.Rows, ds.Columns = DIMS[1], DIMS[0]
        ds.SamplesPerPixel, ds.PhotometricInterpretation = 1, "MONOCHROME2"
        ds.BitsAllocated, ds.BitsStored, ds.HighBit, ds.PixelRepresentation = 16, 16, 15, 1
        ds.RescaleIntercept, ds.RescaleSlope = "0", "1"
        ds.PixelData = np.ascontiguousarray(samples[:, :, k].T).tobytes()  # rows (j) of columns (i)
        ds.save_as(os.path.join(folder, f"slice_{k:03d}.dcm"), write_like_original=False)
    check(folder, 0.5, *dicom_geometry(folder, instance=int(CENTRE[2]) + 1))


def dicom_geometry(folder, instance):
    """Where pydicom's reading of the slices puts pixel (CENTRE i, j) of slice `instance`:
    LPS from its Image Position and Orientation (DICOM PS3.3 C.7.6.2.1.1), and its
    index in the volume, slices sorted along the normal (row x column direction)."""
    slices = [pydicom.dcmread(os.path.join(folder, f)) for f in sorted(os.listdir(folder))]
    orientation = np.array(slices[0].ImageOrientationPatient, dtype=float)
    row_dir, col_dir = orientation[:3], orientation[3:]
    normal = np.cross(row_dir, col_dir)
    slices.sort(key=lambda s: float(np.dot(normal, np.array(s.ImagePositionPatient, dtype=float))))
    k = next(n for n, s in enumerate(slices) if int(s.InstanceNumber) == instance)
    between_rows, between_columns = (float(v) for v in slices[k].PixelSpacing)
    lps = (np.array(slices[k].ImagePositionPatient, dtype=float) + CENTRE[0] * between_columns * row_dir
           + CENTRE[1] * between_rows * col_dir)
    return lps, np.array([CENTRE[0], CENTRE[1], float(k)])


def nrrd_case(name, space, space_affine):
    path = os.path.join(WORK, f"{name}_{space}.nrrd")
    vectors = " ".join("(" + ",".join(f"{v:.17g}" for v in space_affine[:3, a]) + ")" for a in range(3))
    header = (f"NRRD0004\ntype: float\ndimension: 3\nspace: {space}\nsizes: {DIMS[0]} {DIMS[1]} {DIMS[2]}\n"
              f"space directions: {vectors}\nspace origin: ("
              + ",".join(f"{v:.17g}" for v in space_affine[:3, 3]) + ")\nendian: little\nencoding: raw\n\n")
    with open(path, "wb") as f:
        f.write(header.encode("ascii"))
        f.write(np.ascontiguousarray(ball().transpose(2, 1, 0)).astype("<f4").tobytes())  # x fastest
    to_lps = LPS_FROM_RAS if space == "right-anterior-superior" else np.eye(4)
    check(path, 0.0, (to_lps @ space_affine @ np.append(CENTRE, 1.0))[:3])


def main():
    os.makedirs(WORK, exist_ok=True)
    for name, matrix in CASES:
        nifti_case(name, matrix)
        dicom_case(name, matrix)
        nrrd_case(name, "right-anterior-superior", matrix)
        nrrd_case(name, "left-posterior-superior", matrix)
    if failures:
        print(f"{len(failures)} failure(s)")
        sys.exit(1)
    print("every frame agrees with nibabel, pydicom and the NRRD headers")


main()
