// How the rig commands (`ccm rig run`, `ccm rig calibrate`) turn exceptions into messages and
// exit codes: a defect in the inputs, a bad argument or a store that cannot be used is bad input
// (2, "ccm: error: ..."); anything else is an internal error (1, "ccm: internal error: ...").
// What was printed before the failure is flushed first, so the message comes after it.
#pragma once

#include <fmt/format.h>

#include <cstdio>
#include <stdexcept>
#include <string_view>

#include "app/run_command.hpp"
#include "db/sqlite/connection.hpp"
#include "rig_models/core/rig_error.hpp"

namespace ccm {

template <class Body>
int run_rig_reporting_errors(Body&& body) {
  auto fail = [](std::string_view kind, const std::exception& e, int code) {
    std::fflush(stdout);
    fmt::print(stderr, "ccm: {}: {}\n", kind, e.what());
    return code;
  };
  try {
    return body();
  } catch (const rig::RigInputError& e) {
    return fail("error", e, exit_code::bad_input);
  } catch (const std::invalid_argument& e) {
    return fail("error", e, exit_code::bad_input);
  } catch (const db::StoreError& e) {
    return fail("error", e, exit_code::bad_input);
  } catch (const std::exception& e) {
    return fail("internal error", e, exit_code::internal_error);
  }
}

}  // namespace ccm
