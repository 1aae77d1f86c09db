#pragma once
// The studies (accuracy, shape methods, the SPD suite) stop between their renders when a stop is
// requested (core/stop_request.h; the Python module requests one on Ctrl-C). A render cut short
// by the request has blank tiles, so its rows would measure an image that was never finished: the
// study throws StudyStopped instead of returning them, and nothing is written.
#include <stdexcept>
#include <string>

#include "core/stop_request.h"

namespace rayo {

struct StudyStopped : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Throws StudyStopped naming `study` when a stop has been requested.
inline void stop_study_if_requested(const std::string& study) {
    if (stop_requested()) throw StudyStopped(study + ": stopped by a stop request (Ctrl-C)");
}

}  // namespace rayo
