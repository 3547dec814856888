#pragma once
// The one line a command redraws in place on a terminal (a run's progress, a sweep's). Each redraw
// and each clearing goes back to the line's start and erases to its end (ANSI "\033[K"): padding with
// spaces instead wraps on a terminal narrower than the padding and leaves stale lines behind.
#include <string>

namespace frictionlab {

/// Draws `text` over the live line on stderr, without a newline.
void show_live_line(const std::string& text);

/// Erases the live line on stderr, the cursor left at its start for whatever prints next.
void clear_live_line();

}  // namespace frictionlab
