// Every failure of report generation that is not bad input: gnuplot missing or failing, an
// output folder that cannot be written.
#pragma once

#include <stdexcept>

namespace ccm::reports {

class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ccm::reports
