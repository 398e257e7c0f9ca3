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

std::optional<EventType> parseEventType(std::string_view text) {
  for (EventType type :
       {EventType::Impact, EventType::Grazing, EventType::Stick, EventType::Release}) {
    if (toString(type) == text) return type;
  }
  return std::nullopt;
}

}  // namespace grazelab::core
