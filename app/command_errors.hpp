// How the reading commands (status, recommend, report) turn exceptions into messages and exit
// codes: anything the user can fix (a missing, foreign or empty store, a bad argument) is bad
// input (2); anything else is an internal error (1). Messages go to stderr as "ccm: error: ...".
#pragma once

#include <fmt/format.h>

#include <stdexcept>

#include "app/run_command.hpp"
#include "app/study_store_open.hpp"
#include "db/sqlite/connection.hpp"

namespace ccm {

template <class Body>
int run_reporting_errors(Body&& body) {
  auto fail = [](const std::exception& e, int code) {
    fmt::print(stderr, "ccm: error: {}\n", e.what());
    return code;
  };
  try {
    return body();
  } catch (const StudyInputError& e) {
    return fail(e, exit_code::bad_input);
  } catch (const db::StoreError& e) {
    return fail(e, exit_code::bad_input);
  } catch (const std::invalid_argument& e) {
    return fail(e, exit_code::bad_input);
  } catch (const std::exception& e) {
    return fail(e, exit_code::internal_error);
  }
}

}  // namespace ccm
