#include "db/store/row_codes.hpp"

#include <cstdlib>
#include <sstream>

namespace ccm::db {

RunStatus run_status_from_text(const std::string& text) {
  for (const RunStatus s :
       {RunStatus::running, RunStatus::completed, RunStatus::unstable, RunStatus::failed})
    if (to_string(s) == text) return s;
  throw StoreError("unknown run status \"" + text + "\" in the store");
}

study::ImpactModel model_from_text(const std::string& text) {
  if (text == "ccm") return study::ImpactModel::ccm;
  if (text == "rigid") return study::ImpactModel::rigid;
  throw StoreError("unknown model \"" + text + "\" in the store");
}

std::map<std::string, double> other_axes_from_text(const std::string& text) {
  std::map<std::string, double> axes;
  std::istringstream items(text);
  for (std::string item; std::getline(items, item, ';');) {
    const auto eq = item.find('=');
    if (eq == std::string::npos) continue;
    axes[item.substr(0, eq)] = std::strtod(item.c_str() + eq + 1, nullptr);
  }
  return axes;
}

study::GridPoint point_from_row(const Statement& row, int first) {
  study::GridPoint p;
  p.index = static_cast<int>(row.column_int(first));
  p.modulus_ratio = row.column_double(first + 2);
  p.length_ratio = row.column_double(first + 3);
  p.kinetic_energy = row.column_double(first + 4);
  p.other_axes = other_axes_from_text(row.column_text(first + 5));
  return p;
}

}  // namespace ccm::db
