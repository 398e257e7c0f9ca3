// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#include "core/solver/events.h"

namespace grazelab::core {

std::string_view toString(EventType type) {
  switch (type) {
    case EventType::Impact:
      return "impact";
    case EventType::Grazing:
      return "grazing";
    case EventType::Stick:
      return "stick";
    case EventType::Release:
      return "release";
  }
  return "unknown";
}

std::string_view toString(StopReason reason) {
  switch (reason) {
    case StopReason::ContactLimit:
      return "contact-limit";
    case StopReason::TimeLimit:
      return "time-limit";
    case StopReason::NoFurtherContact:
      return "no-further-contact";
    case StopReason::SearchBudget:
      return "search-budget";
    case StopReason::Undecided:
      return "undecided";
    case StopReason::Cancelled:
      return "cancelled";
    case StopReason::InvalidInput:
      return "invalid-input";
  }
  return "unknown";
}

std::optional<EventType> parseEventType(std::string_view text) {
  for (EventType type :
       {EventType::Impact, EventType::Grazing, EventType::Stick, EventType::Release}) {
    if (toString(type) == text) return type;
  }
  return std::nullopt;
}

}  // namespace grazelab::core
