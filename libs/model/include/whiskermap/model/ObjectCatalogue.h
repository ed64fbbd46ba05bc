#pragma once
#include <whiskermap/model/ObjectClass.h>

#include <string>
#include <vector>

namespace whiskermap::model
{
/** The object catalogue file (config/objects.ini; format in doc/formats.md): one [name]
 *  section per class, each with exactly the keys length, width, leg_width, texture,
 *  size_sigma and prior, and optionally label (the class it reports; default its name). */
struct ObjectCatalogue
{
	static constexpr size_t MAX_CLASSES = 16;

	/** Reads `path` strictly: unknown, missing or repeated keys, a repeated class, a bad class
	 *  name, a non-positive size, a leg as wide as the object, a prior outside (0, 1] or
	 *  priors not summing to 1 are core::Error "FILE: line N: [class] KEY: problem". Classes
	 *  keep the file's order (their index is what map streams store). */
	static std::vector<ObjectClass> load(const std::string& path);
};
}  // namespace whiskermap::model
