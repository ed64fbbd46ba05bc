#pragma once
#include <array>
#include <cstddef>
#include <string>

namespace whiskermap::world
{
/** The class label of a four-legged object ("table", "desk", "chair", ...): 1 to 31 letters,
 *  digits or _. Stored inline, so that world::Table stays trivially copyable (the Python
 *  module hands tables to numpy as packed records). Default: "table". */
class ObjectClass
{
   public:
	static constexpr size_t MAX_LENGTH = 31;

	ObjectClass() = default;
	/** Throws std::invalid_argument when `name` is not valid(). */
	explicit ObjectClass(const std::string& name);

	/** True for 1 to MAX_LENGTH letters, digits or _. */
	static bool valid(const std::string& name);

	std::string str() const { return m_name.data(); }
	bool operator==(const ObjectClass& o) const { return m_name == o.m_name; }
	bool operator!=(const ObjectClass& o) const { return m_name != o.m_name; }

   private:
	std::array<char, MAX_LENGTH + 1> m_name{'t', 'a', 'b', 'l', 'e'};
};
}  // namespace whiskermap::world
