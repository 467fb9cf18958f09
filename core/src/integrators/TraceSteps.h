#pragma once

#include "raylab/core/PixelTrace.h"

#include <functional>
#include <optional>

namespace raylab {

/**
 * \brief The one loop that runs the real algorithm ray by ray for one (pixel, sample) and
 * keeps what each step did (StepEvent): behind tracePixel, traceRay and the student's trace
 * (StudentTrace.cpp). Private to core.
 *
 * Traces sample `sample` of pixel (x, y) of `tracer`, from `root` in place of the camera ray
 * when set, within `limits` (a cancel ends it early: PixelTrace::cancelled). `step` advances
 * the stepper by one ray (Stepper::step when empty): a caller that tags what each step did
 * (the student's calls) wraps it.
 */
PixelTrace traceSteps(const Tracer& tracer, int x, int y, int sample, const TraceLimits& limits,
                      const std::optional<Ray>& root,
                      const std::function<void(Stepper&)>& step = {});

}  // namespace raylab
