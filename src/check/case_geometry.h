// A check case's own geometry, for the split of its pixels into edges and interiors
// (check/pixel_classes.h): read from the surfaces the shading oracle reads back after the frame
// (check/oracle_inputs.h), so it exists on every tier the oracle runs on (the G-buffer of every
// layout; forward's surfaces drawn again; depth and stencil drawn out where ES cannot read them).
#pragma once
#include "check/oracle_inputs.h"
#include "check/pixel_classes.h"

namespace oasis {

// Sky where no surface was drawn, plants by their surface flag, water by its stencil mark; the
// distance and normal of every other pixel as the lighting decoded them. Rows top row first.
PixelGeometry caseGeometry(const OracleInputs& inputs);

}  // namespace oasis
