#include "reports/data/report_data.hpp"

namespace ccm::reports {

bool is_convergence_point(const study::GridPoint& point) {
  return point.other_axes.contains("mesh_scale");
}

}  // namespace ccm::reports
