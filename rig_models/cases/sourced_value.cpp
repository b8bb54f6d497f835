#include "rig_models/cases/sourced_value.hpp"

#include <fmt/format.h>

namespace ccm::rig {

SourcedValue read_sourced(const StrictTable& parent, std::string_view key, std::string_view unit,
                          ValueBound bound) {
  const StrictTable t = parent.need_table(key);
  t.allow_only({"value", "unit", "source"});
  SourcedValue v{t.need_number("value"), t.need_string("unit"), t.need_string("source")};
  if (v.unit != unit) t.fail("unit", fmt::format("must be '{}' (got '{}')", unit, v.unit));
  const bool ok = bound.strictly ? v.value > bound.minimum : v.value >= bound.minimum;
  if (!ok)
    t.fail("value", fmt::format("must be {} {} (got {})",
                                bound.strictly ? ">" : ">=", bound.minimum, v.value));
  return v;
}

}  // namespace ccm::rig
