#pragma once
#include <stdexcept>
#include <string>

namespace whiskermap::core
{
/** The one exception type whiskermap throws for bad input (files, configs, values).
 *  Its message is a single line that names the file (or object) and the problem, ready to
 *  print as-is by an app before it exits non-zero. */
class Error : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};
}  // namespace whiskermap::core
