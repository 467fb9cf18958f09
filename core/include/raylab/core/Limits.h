#pragma once

#include <cstddef>
#include <cstdint>

/// \file Limits.h
/// The limits RayLab puts on what a file or a command line may ask for, in one place: the
/// scene and lesson loaders, the mesh readers and the command line refuse a value past
/// one of these with a message naming the file, the place and the limit, so no input
/// brings the machine down with a huge allocation or a computation that never ends.
/// README.md ("Limits") lists them for users; each has a regression test.

namespace raylab::limits {

/// Largest scene or lesson file read, bytes (a 64 MiB JSON document takes about 1 GB of
/// memory once parsed).
constexpr std::uint64_t kMaxJsonFileBytes = std::uint64_t(64) << 20;
/// Deepest nesting of JSON arrays and objects in a scene or lesson file (a scene needs 8).
constexpr int kMaxJsonDepth = 64;

/// Largest image side, pixels (the command line's --size too).
constexpr int kMaxImageSide = 8192;
/// Largest image, pixels (width x height): 4096 x 4096. A render keeps a few doubles per
/// pixel, so this is about 1 GB at most.
constexpr std::int64_t kMaxImagePixels = std::int64_t(4096) * 4096;
/// Most samples per pixel (scene files and --spp).
constexpr int kMaxSamplesPerPixel = 1 << 20;
/// Deepest bounce (max_depth): the camera ray has depth 0.
constexpr int kMaxDepth = 64;
/// Most shadow rays per area light, and glossy rays, at one hit (distributed tracing).
constexpr int kMaxLightSamples = 256;
/// Most rays one camera sample of an image may trace (Tracer::trace), the camera ray and
/// every ray queued after it included. Within the limits above a distributed sample can
/// still ask for 256^64 rays; past this cap no ray of the sample spawns children any more
/// (the rays already queued are traced), so one sample costs at most this many rays (a
/// quarter of a second on one core for the bushy test room) and 11 MB of queue per
/// thread. The renderer counts such samples (RenderStats::cappedSamples) and `raylab
/// render` and `compare` warn. A ray tree stops at its 16 MiB budget (kDefaultTreeBudget,
/// about 60,000 rays) first, so a tree `raylab trace` records whole is never capped.
constexpr std::size_t kMaxRaysPerSample = std::size_t(1) << 16;

/// Most worker threads of one render (--threads, Python's `threads`): each thread takes a
/// stack of 8 MiB of address space, and a render has at most 65,536 tiles to share.
constexpr int kMaxThreads = 256;

/// Smallest and largest index of refraction (`ior`, `ior_outside`): real media lie between
/// 1 and about 4; past these the refracted and reflected directions of the classic
/// materials lose all their digits.
constexpr double kMinIor = 0.01;
constexpr double kMaxIor = 100.0;

/// Most steps of one lesson file.
constexpr std::size_t kMaxLessonSteps = 1000;
/// Most scene changes of one lesson, all steps together (each is applied to the scene file
/// once, and the changed scene read once per step).
constexpr std::size_t kMaxLessonSceneChanges = 10'000;
/// Most sample directions a lesson's samples view draws (`samples.count`).
constexpr int kMaxLessonSamples = 1 << 16;
/// The work budget of one lesson's computed answers and samples: the camera samples of its
/// checked answers (`check.spp`, each a pixel's sample) plus the directions of its samples
/// views, all steps together. Checked when the lesson is read, before any work; 4,194,304
/// camera samples of a lesson scene take a few seconds on one core.
constexpr std::int64_t kMaxLessonWork = std::int64_t(1) << 22;

/// Largest reference-cache sidecar read, bytes (a real one is under 2 kB).
constexpr std::uint64_t kMaxCacheSidecarBytes = std::uint64_t(1) << 20;

/// Largest magnitude of a coordinate, size or radius, world units: squares and products of
/// such numbers stay far from overflowing a double.
constexpr double kMaxCoordinate = 1e12;
/// Smallest size, radius or scale factor (and the shortest vector that may give a
/// direction): their squares stay far from underflowing a double.
constexpr double kMinLength = 1e-9;

/// Most slices of a sphere's tessellation, m (polar) and n (azimuthal) each.
constexpr int kMaxSphereSlices = 1024;
/// Most triangles (and vertices) of one mesh file.
constexpr std::size_t kMaxMeshTriangles = 4'000'000;
/// Most corners of one polygonal face of a mesh file: a face is checked to be a simple polygon
/// before it is triangulated, in time quadratic in its corners.
constexpr std::size_t kMaxFaceCorners = 4096;
/// Most corners of all the faces of one mesh file together (a face's corners are read,
/// checked and triangulated in time linear in them, or quadratic in one face's: see below).
constexpr std::size_t kMaxMeshCorners = 3 * kMaxMeshTriangles;
/// The work of checking every polygonal face simple, the sum over faces of corners squared:
/// 64M, a second or two (4,096 faces of 4,096 corners would take a quarter of an hour).
constexpr std::uint64_t kMaxFaceCheckWork = std::uint64_t(1) << 26;
/// Largest mesh file read, bytes.
constexpr std::uint64_t kMaxMeshFileBytes = std::uint64_t(1) << 30;

}  // namespace raylab::limits
