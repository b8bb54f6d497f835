// How the reading commands (status, recommend, report) turn exceptions into messages and exit
// codes: anything the user can fix (a missing, foreign or empty store, a bad argument) is bad
// input (2); anything else is an internal error (1). Messages go to stderr as "ccm: error: ...".
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <string_view>

#include "app/run_command.hpp"
#include "app/study_store_open.hpp"
#include "config/config_error.hpp"
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

// How the commands that run a scene (compare, validate) do the same: the scene's, the data's or
// an argument's problem (ConfigError, std::invalid_argument) and a --db store that cannot be
// used are bad input (2), reported before anything runs; anything else is an internal error (1).
template <class Body>
int run_scene_command(Body&& body) {
  auto fail = [](std::string_view prefix, std::string_view what, int code) {
    fmt::print(stderr, "ccm: {}{}\n", prefix, what);
    return code;
  };
  try {
    return body();
  } catch (const ConfigError& e) {
    return fail("error: ", e.what(), exit_code::bad_input);
  } catch (const std::invalid_argument& e) {
    return fail("error: ", e.what(), exit_code::bad_input);
  } catch (const db::StoreError& e) {
    return fail("error: --db ", e.what(), exit_code::bad_input);
  } catch (const std::exception& e) {
    return fail("internal error: ", e.what(), exit_code::internal_error);
  } catch (const std::string& e) {  // Gmsh throws its messages as strings
    return fail("internal error: ", e, exit_code::internal_error);
  }
}

}  // namespace ccm
