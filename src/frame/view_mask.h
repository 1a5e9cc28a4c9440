// Which pixels of a debug view hold a drawn surface: the views whose values mean nothing where
// nothing was drawn (the sky: cleared or never written G-buffer texels) count, range and overlay
// only the drawn pixels, as the depth view shows its cleared pixels black.
#pragma once
#include <string>

#include "debug/debug_views.h"
#include "debug/view_controls.h"

namespace oasis {

class Renderer;

// Whether the view's values are masked to drawn pixels: the G-buffer surface views (albedo,
// normal, position, light-volumes, shadow), by the Info target's sky flag. Not the depth view (its
// cleared pixels hold the far plane's distance, a value, and it draws them black already), the
// info view (its flags say "sky"), the stencil or the light views.
bool masksUndrawn(const DebugView& view);
// The mask for the frame in the renderer's targets (bottom row first, as the values); empty for
// a view that is not masked.
DrawnPixels drawnPixels(Renderer& renderer, const DebugView& view);
// The legend's line for a masked view whose values are shown (the sky black), else "".
std::string undrawnNote(const DebugView& view, long undrawn, bool valuesShown);

}  // namespace oasis
