#include <whiskermap/core/conciseMessage.h>

#include <sstream>

namespace whiskermap::core
{
std::string conciseMessage(const std::exception& e)
{
	const std::string what = e.what();
	std::istringstream in(what);
	std::string line, best, prev;
	const std::string msgTag = "Message:", banner = "==== MRPT exception ====";
	while (std::getline(in, line))
	{
		if (line.rfind(msgTag, 0) == 0)
		{
			const auto b = line.find_first_not_of(' ', msgTag.size());
			best = b == std::string::npos ? std::string() : line.substr(b);
		}
		else if (prev == "Original exception:" && line != banner)
			best = line;
		prev = line;
	}
	if (best.empty()) best = what.substr(0, what.find('\n'));
	if (best.find("Cannot read requested number of bytes") != std::string::npos)
		return "truncated file (an object is cut off)";
	return best;
}
}  // namespace whiskermap::core
