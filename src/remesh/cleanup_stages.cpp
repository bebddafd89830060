// The clean-up's schedule, see cleanup_stages.hpp; remesh.cpp runs it.
#include "remesh/cleanup_stages.hpp"

namespace isopatch {

CleanupSchedule cleanup_schedule(const RemeshSettings& settings) {
  using namespace cleanup_stages;
  CleanupSchedule schedule;
  schedule.setup = {kSizes};
  if (settings.local_only) {
    schedule.finish = {kCollapse, kRepair, kFlip, kSizes, kRelax, kRepair, kFlip, kRelax, kRepair};
    if (settings.valence_search > 0)
      schedule.finish.insert(schedule.finish.end(), {kValenceSearch, kRelax, kRepair});
    return schedule;
  }
  schedule.round = {kSplit, kSizes, kCollapse, kSizes, kFlip, kRelax, kSizes};
  schedule.finish = {kRepair, kSizes, kFlip, kRelax};
  if (settings.valence_search > 0) schedule.finish.push_back(kValenceSearch);
  schedule.finish.push_back(kRelax);
  if (settings.curvature_sweeps > 0) schedule.finish.push_back(kCurvature);
  schedule.finish.push_back(kRepair);
  if (settings.sizes.max_error) schedule.finish.push_back(kErrorBound);
  return schedule;
}

}  // namespace isopatch
