// SPDX-License-Identifier: MIT
// SPDX-FileCopyrightText: 2026 GrazeLab developers
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "core/model/state.h"

namespace grazelab::core {

/// What happens when mass 2 reaches the stop (docs/model.md section 4).
enum class EventType : std::uint8_t {
  Impact,   ///< arrives with v2 > 0 and leaves with -v2 (elastic, e = 1)
  Grazing,  ///< touches with v2 = 0 and is pulled away: the flight goes on unchanged
  Stick,    ///< touches (or starts) with v2 = 0 pressed into the stop: a stuck phase begins
  Release,  ///< the spring force on mass 2 falls to zero: the stuck phase ends, flight begins
};

/// "impact", "grazing", "stick", "release".
std::string_view toString(EventType type);
std::optional<EventType> parseEventType(std::string_view text);

/// True for the events that are contacts with the stop (all but Release).
inline bool isContact(EventType type) { return type != EventType::Release; }

/// One event: when, what, and the state just before and just after it.
template <typename S>
struct BasicEvent {
  S t = 0;  ///< time since the start of the run [time]
  EventType type = EventType::Impact;
  BasicState<S> before;  ///< state before the event (v2 = v2_pre)
  BasicState<S> after;   ///< state after the event (v2 = v2_post)

  friend bool operator==(const BasicEvent&, const BasicEvent&) = default;
};

using Event = BasicEvent<double>;

}  // namespace grazelab::core
