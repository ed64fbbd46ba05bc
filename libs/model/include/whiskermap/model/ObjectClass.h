#pragma once
#include <string>
#include <tuple>

namespace whiskermap::model
{
/** One four-legged object class of the catalogue (config/objects.ini, doc/formats.md): its
 *  nominal leg-centre spacings, leg width and texture, the spread of its sizes and its prior
 *  probability among the classes. A table hypothesis of this class has these dimensions. */
struct ObjectClass
{
	std::string name = "table";  ///< 1 to 31 letters, digits or _: the section name
	std::string label = "table";  ///< the class column of map_tables.csv (optional key; default: name)
	double length = 1.0;  ///< leg-centre spacing along the object's x axis, metres
	double width = 0.6;  ///< leg-centre spacing along its y axis, metres
	double leg_width = 0.05;  ///< side of a square leg, metres
	double texture = 0.7;  ///< texture of its legs, in [0, 1]
	double size_sigma = 0.02;  ///< spread of length and width around the nominal ones, metres
	double prior = 1.0;  ///< prior probability of the class (the catalogue's sum to 1)
	/** Spread of an object's leg width around the nominal one, metres (eq. 26); 0: every
	 *  object has the nominal leg width (optional key, default 0). */
	double leg_width_sigma = 0;
	double texture_sigma = 0;  ///< spread of its leg texture around the nominal one (eq. 26); 0: nominal

	/** Whether its objects' leg width or texture may differ from its nominal ones (eq. 26). */
	bool legsVary() const { return leg_width_sigma > 0 || texture_sigma > 0; }

	bool operator==(const ObjectClass& o) const
	{
		auto tie = [](const ObjectClass& c) {
			return std::tie(c.name, c.label, c.length, c.width, c.leg_width, c.texture, c.size_sigma, c.prior, c.leg_width_sigma, c.texture_sigma);
		};
		return tie(*this) == tie(o);
	}
};
}  // namespace whiskermap::model
