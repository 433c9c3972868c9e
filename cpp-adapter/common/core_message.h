// The core's reason for its last failure, for a message that names the
// deck's command: the core's message leads with the C entry that failed
// (ffi/error.rs), which a deck's user never wrote.
#ifndef GRANBOND_CORE_MESSAGE_H
#define GRANBOND_CORE_MESSAGE_H

#include "granbond.h"

#include <cstring>
#include <string>

namespace granbond {

inline std::string coreReason()
{
    const char *m = granbond_last_error_message();
    const char *colon = std::strstr(m, ": ");
    if (std::strncmp(m, "granbond_", 9) == 0 && colon && std::strcspn(m, " ") > static_cast<size_t>(colon - m))
        return colon + 2;
    return m;
}

}

#endif
