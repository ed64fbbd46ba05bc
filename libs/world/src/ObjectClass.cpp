#include <whiskermap/world/ObjectClass.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace whiskermap::world
{
ObjectClass::ObjectClass(const std::string& name)
{
	if (!valid(name)) throw std::invalid_argument("'" + name + "' is not an object class name");
	m_name.fill('\0');
	std::copy(name.begin(), name.end(), m_name.begin());
}

bool ObjectClass::valid(const std::string& name)
{
	return !name.empty() && name.size() <= MAX_LENGTH &&
		std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_'; });
}
}  // namespace whiskermap::world
