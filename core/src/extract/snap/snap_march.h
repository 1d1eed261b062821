#pragma once
// The snap room: extraction with the 3-state table (isotrack/snap_table.h):
// marching cubes, the surface through a seed, and every surface, over sample
// states decided once for the volume (snap_states.cpp); the cells all share
// are in snap_cells.h, the surface through a seed on several threads in
// snap_together.cpp. It uses the tables, common/ (and its tiles), tracking/
// (the walker, the continuation it follows, the mailboxes), trilinear/ (its
// walk's interface and its parts' join) and mesh/ (welding, fins);
// marching_cubes/, surfaces/ and tracking/ call it for TableKind::Snap.
#include <cstdint>
#include <memory>
#include <vector>

#include "extract/trilinear/trilinear_march.h"
#include "isotrack/mesh.h"
#include "isotrack/snap_table.h"
#include "isotrack/surface.h"
#include "isotrack/volume.h"

namespace isotrack::detail {

// Every sample's state after snapping, in sample order: its side of `iso`, and
// at when it equals `iso` or when a crossing on one of its grid edges lies
// within kSnapDistance of it (snapsTowards, with the samples as they are, not
// as snapped), unless that would lay two sheets on one grid edge
// (snap_states.cpp). The same states on any number of `threads`.
std::vector<SampleState> snapStates(const Volume& volume, double iso, int threads);

// removeFins (mesh/manifold.h) where only the triangles `suspects` (their
// places, in increasing order) can have a twin over the same three vertices:
// the same triangles go, the others keep their order. Returns the indices kept
// (at the front of `indices`, which held `indexCount`).
std::size_t removeFinsAmong(std::uint32_t* indices, std::size_t indexCount, const std::vector<std::uint32_t>& suspects);

// Every cell, one mesh: one vertex per crossed grid edge whose ends are both
// off the isovalue, one per sample at the isovalue that a triangle uses (its
// vertexEdges entry is a grid edge from or to the sample, on the volume's
// border when the sample is). Pairs of triangles over the same three vertices
// are removed (removeFinsAmong).
// The states are decided on `threads` threads; the cells are emitted on one,
// so the mesh is the same, byte for byte, on any number.
Mesh marchSnap(const Volume& volume, double iso, int threads);

// The surface through `seed` by continuation over the 2-state configurations
// the snapped ones refine (the consistent table's), walked breadth-first a budget of (cell, piece) pairs
// at a time; the walk's interface is the trilinear table's (TrilinearWalk).
// InputError when the seed is outside or not crossed. `threads` decide the
// states (snapStates); the walk itself is on the caller's thread.
std::unique_ptr<TrilinearWalk> startSnap(const Volume& volume, double iso, const GridEdge& seed, int threads = 1);

// The walk's surface (its mesh taken), its reversed pairs removed, measured
// (the closing check on `threads` threads).
Surface finishedSnap(TrilinearWalk& walk, const Volume& volume, int threads = 1);

// The states, the walk and the closing check on up to `threads` threads (as
// many as the volume's tiles share out, kMaxTrackThreads at most): on one,
// startSnap's walk; on several, trackSnapTogether's. The same triangles over
// the same vertices on any number of threads (in an order that depends on
// them, unless the surface is done within the first pieces, walked alone).
Surface trackSnap(const Volume& volume, double iso, const GridEdge& seed, int threads);

// The surface through `seed` walked on `threads` (> 1) threads, each walking
// its own tiles, the parts joined and measured on them (snap_together.cpp).
Surface trackSnapTogether(const Volume& volume, double iso, const GridEdge& seed, int threads);

// Every surface by continuation from each (cell, piece) no walk has visited,
// most triangles first; surfaces that snapping collapses to nothing are dropped.
// The states on `threads` threads, the walks on one: the same surfaces on any number.
std::vector<Surface> allSnap(const Volume& volume, double iso, int threads);

}  // namespace isotrack::detail
