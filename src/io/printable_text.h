// Text that came from outside oasis (file names, PNG text chunks, report fields, request targets),
// made safe to print: a terminal must never receive a control byte oasis did not mean to send (an
// ESC sequence in a received PNG could erase lines or fake them; a NUL cuts C strings). The one
// function every such message goes through (issue 42, item 4).
#pragma once
#include <string>

namespace oasis {

// `text` with what a terminal could act on spelled out as JSON spells it: \n \r \t, the other C0
// controls, DEL and the C1 controls (U+0080..U+009F; 0x9B is a CSI on some terminals) as \u00XX,
// and the backslash itself as \\, so that an escape seen is never one that was in the text. A byte
// that is not part of valid UTF-8 becomes \xHH (JSON cannot hold it). Valid printable UTF-8 is
// kept as it is.
std::string printableText(const std::string& text);

// `text` with every byte that is not part of valid UTF-8 replaced by U+FFFD (a path in a command
// line may be in another encoding; a PNG's iTXt and JSON hold UTF-8 only).
std::string validUtf8(const std::string& text);

}  // namespace oasis
