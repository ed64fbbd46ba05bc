#pragma once

namespace whiskermap::cli
{
/** The whisker-worldgen command line: generate one evaluation world and its robot path
 *  (world::WorldGenerator) and write them as PREFIX.ini and PREFIX.path.
 *  `whisker-worldgen --help` lists the options; doc/eval-worlds.md describes the categories. */
struct WhiskerWorldgenApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
