#pragma once
#include <string>

namespace whiskermap::core
{
/** Finds shipped config files (config/ in the source tree, or share/whiskermap/config once
 *  installed) so apps accept bare preset names such as `--noise very-noisy`. */
struct ConfigPaths
{
	/** The first existing of: $WHISKERMAP_CONFIG_DIR/rel, <source>/config/rel,
	 *  <prefix>/share/whiskermap/config/rel. Throws core::Error listing where it looked. */
	static std::string find(const std::string& rel);

	/** `arg` itself if it names an existing file, else find(subdir + "/" + arg + ".ini"). */
	static std::string resolve(const std::string& arg, const std::string& subdir);
};
}  // namespace whiskermap::core
