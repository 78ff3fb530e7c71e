// The core's messages in the user's language: session/core_message.hpp (Qt Core, so the session
// layer translates the motion check's refusals with the same function).
#pragma once

#include "session/core_message.hpp"

namespace fivebar::widgets {

using session::translated;

}  // namespace fivebar::widgets
