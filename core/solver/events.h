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

/// Why a run ended, for two masses and N.
enum class StopReason {
  ContactLimit,      ///< maxContacts reached
  TimeLimit,         ///< tEnd reached
  NoFurtherContact,  ///< a resonant (commensurate) flight that stays below the stop for a whole
                     ///< period, any flight whose modes' amplitudes together fall short of the
                     ///< stop, or a floating chain's drifting away from it: linear forever
  SearchBudget,      ///< no contact (or release) decided within the search's horizon and budget
                     ///< (a chain that is not resonant)
  Undecided,         ///< a contact the precision cannot decide: a top of the stopped mass within
                     ///< rounding of the stop (a grazing, a slow impact and a miss all fit), or at
                     ///< rest there with no force either way, or held there by a force that comes
                     ///< back to 0 without being seen to change sign; the run ends at that
                     ///< flight's start (--precision auto goes on in a higher precision)
  Cancelled,         ///< the stop token was triggered
  InvalidInput,      ///< the model or the initial state is unusable (see message)
};
/// "contact-limit", "time-limit", "no-further-contact", "search-budget",
/// "undecided", "cancelled", "invalid-input".
std::string_view toString(StopReason reason);

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
