#pragma once

namespace whiskermap::cli
{
/** The whisker-export command line: a rawlog of whisker sweeps (either layout) to a text
 *  contact log (doc/formats.md). `whisker-export --help` lists options. */
struct WhiskerExportApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
