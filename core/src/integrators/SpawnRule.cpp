#include "raylab/core/SpawnRule.h"

#include "integrators/distributed/DistributedRule.h"
#include "integrators/path/PathTracingRule.h"
#include "integrators/raycast/RayCastingRule.h"
#include "integrators/whitted/WhittedRule.h"

namespace raylab {

std::unique_ptr<SpawnRule> SpawnRule::create(const RenderSettings& settings) {
  switch (settings.algorithm) {
    case Algorithm::RayCasting:
      return std::make_unique<RayCastingRule>();
    case Algorithm::Whitted:
      return std::make_unique<WhittedRule>();
    case Algorithm::Distributed:
      return std::make_unique<DistributedRule>();
    case Algorithm::PathTracing:
      return std::make_unique<PathTracingRule>();
  }
  return std::make_unique<PathTracingRule>();
}

}  // namespace raylab
