#include "src/brep/boolean/boolean_alerts.hpp"

#include <Message_Alert.hxx>

namespace cg::features {

std::vector<std::string> alert_names(const Handle(Message_Report) & report, Message_Gravity gravity) {
  std::vector<std::string> out;
  if (report.IsNull()) return out;
  for (const Handle(Message_Alert)& a : report->GetAlerts(gravity)) out.emplace_back(a->GetMessageKey());
  return out;
}

std::string alert_summary(const Handle(Message_Report) & report) {
  std::string s;
  const auto add = [&](const char* what, const std::vector<std::string>& names) {
    if (names.empty()) return;
    s += (s.empty() ? "" : "; ") + std::string(what) + ": ";
    for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  };
  add("errors", alert_names(report, Message_Fail));
  add("warnings", alert_names(report, Message_Warning));
  return s.empty() ? "no alerts" : s;
}

}  // namespace cg::features
