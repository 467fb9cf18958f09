#pragma once

namespace raylab {

/// Deepest tree the traversal stack can hold (BvhTraverse.cpp); the builder stops using
/// SAH splits well before this (kSahDepthLimit) and halves ranges by index instead, and
/// checks that the finished tree fits (BvhBuild.cpp). Private to core.
constexpr int kBvhStackSize = 128;
/// Depth from which the builder splits ranges at their middle instead of by SAH.
constexpr int kBvhSahDepthLimit = 64;

}  // namespace raylab
