#include <whiskermap/core/Error.h>
#include <whiskermap/core/IniSection.h>
#include <whiskermap/model/ObjectCatalogue.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace whiskermap::model
{
namespace
{
bool validName(const std::string& n)
{
	return !n.empty() && n.size() <= 31 &&
		   std::all_of(n.begin(), n.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}
}  // namespace

std::vector<ObjectClass> ObjectCatalogue::load(const std::string& path)
{
	const auto file = core::openIniFile(path, "object catalogue");
	std::vector<ObjectClass> classes;
	double sum = 0;
	for (const std::string& name : file->sectionsInOrder())
	{
		core::IniSection sec(*file, name, path);
		if (!validName(name)) sec.fail("", "class name must be 1 to 31 letters, digits or _");
		if (classes.size() == MAX_CLASSES) sec.fail("", "more than " + std::to_string(MAX_CLASSES) + " classes");
		ObjectClass c;
		c.name = name;
		c.label = sec.text("label", name);
		if (!validName(c.label)) sec.fail("label", "'" + c.label + "' is not a class name (1 to 31 letters, digits or _)");
		c.length = sec.number("length", 1e-3, 100);
		c.width = sec.number("width", 1e-3, 100);
		c.leg_width = sec.number("leg_width", 1e-4, 10);
		c.texture = sec.number("texture", 0, 1);
		c.size_sigma = sec.number("size_sigma", 1e-6, 10);
		c.prior = sec.number("prior", 1e-12, 1);
		c.leg_width_sigma = sec.number("leg_width_sigma", 0, 0, 1);
		c.texture_sigma = sec.number("texture_sigma", 0, 0, 1);
		sec.finish();
		if (c.leg_width >= std::min(c.length, c.width)) sec.fail("leg_width", "must be smaller than length and width");
		sum += c.prior;
		classes.push_back(c);
	}
	if (classes.empty()) throw core::Error(path + ": no class (expected at least one [name] section)");
	if (std::abs(sum - 1) > 1e-6)
		core::IniSection(*file, classes.back().name, path).fail("prior", "the classes' priors sum to " + std::to_string(sum) + ", not 1");
	return classes;
}
}  // namespace whiskermap::model
