#include <CLI/CLI.hpp>
#include <whiskermap/cli/RawlogFormatOption.h>

namespace whiskermap::cli
{
void RawlogFormatOption::add(CLI::App& app, std::string& value)
{
	app.add_option(
		   "--format", value,
		   "obs: odometry + observations; action-sf: actions + sensory frames (for rbpf-slam)")
		->check(CLI::IsMember({"obs", "action-sf"}))
		->capture_default_str();
}

world::RawlogWriter::Format RawlogFormatOption::parse(const std::string& value)
{
	return value == "action-sf" ? world::RawlogWriter::Format::ActionSensoryFrame
								: world::RawlogWriter::Format::Observations;
}
}  // namespace whiskermap::cli
