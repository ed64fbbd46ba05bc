#pragma once
#include <exception>
#include <string>

namespace whiskermap::core
{
/** The one line that matters in an exception's message. MRPT's span many lines and nest
 *  ("==== MRPT exception ====", "Message: ...", "Original exception:" + the cause, a call
 *  stack): this keeps the innermost cause; other messages give their first line. A stream
 *  that ran dry mid-object reads "truncated file (an object is cut off)". */
std::string conciseMessage(const std::exception& e);
}  // namespace whiskermap::core
