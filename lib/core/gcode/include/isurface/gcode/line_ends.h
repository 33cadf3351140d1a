// Line ends as files from every system write them: LF, CR LF, and CR alone (old Mac editors and
// some controls' file transfer).
#pragma once

#include <string>
#include <string_view>

namespace isurface {

// Whether a carriage return ends a line without a line feed after it anywhere in `text`.
bool hasLoneCarriageReturn(std::string_view text);

// `text` with each lone carriage return made a line feed (CR LF is left as it is), so that a
// reader splitting at line feeds sees the lines the file's author saw.
std::string withLineFeeds(std::string_view text);

}  // namespace isurface
