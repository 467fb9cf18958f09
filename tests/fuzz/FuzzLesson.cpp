// libFuzzer target: the lesson loader (LessonIO::parse), with the shipped lessons' folder
// as its origin so "scene" names resolve to the shipped scenes; its scene changes (seeds:
// the shipped lessons, which change scenes, and tests/data/stranger's lessons) are
// applied and the changed scenes read as the loader does. An input is refused with a
// LessonIO::LoadError or loads, within the lesson's budget of counts (issue 38); anything
// else (another exception, a sanitizer report, a timeout, a huge allocation) is a finding.
// A loaded lesson's samples views draw their directions.
#include "raylab/core/Lesson.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const raylab::Lesson lesson = raylab::LessonIO::parse(
        std::string(reinterpret_cast<const char*>(data), size), RAYLAB_FUZZ_LESSON_ORIGIN);
    for (const raylab::LessonStep& step : lesson.steps)
      if (step.samples) step.samples->directions(step.scene->render.seed);
  } catch (const raylab::LessonIO::LoadError&) {
  }
  return 0;
}
