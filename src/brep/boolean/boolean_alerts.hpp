#pragma once
// BOPAlgo alerts (errors and warnings of OCCT's boolean algorithms) as names, for reports and messages.
// Every warning counts as a failure of the verified boolean path (see the booleans notes: the only
// signs of silently wrong results were warnings such as BOPAlgo_AlertTooSmallEdge).
#include <Message_Gravity.hxx>
#include <Message_Report.hxx>

#include <string>
#include <vector>

namespace cg::features {

/// Alert class names of one gravity, e.g. "BOPAlgo_AlertTooSmallEdge", in report order.
std::vector<std::string> alert_names(const Handle(Message_Report) & report, Message_Gravity gravity);

/// "errors: A, B; warnings: C" (empty parts left out; "no alerts" when there are none).
std::string alert_summary(const Handle(Message_Report) & report);

}  // namespace cg::features
