// libFuzzer target: the lesson loader (LessonIO::parse), with the shipped lessons' folder
// as its origin so "scene" names resolve to the shipped scenes. An input is refused with a
// LessonIO::LoadError or loads; anything else (another exception, a sanitizer report, a
// timeout, a huge allocation) is a finding.
#include "raylab/core/Lesson.h"

#include <cstddef>
#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    raylab::LessonIO::parse(std::string(reinterpret_cast<const char*>(data), size),
                            RAYLAB_FUZZ_LESSON_ORIGIN);
  } catch (const raylab::LessonIO::LoadError&) {
  }
  return 0;
}
