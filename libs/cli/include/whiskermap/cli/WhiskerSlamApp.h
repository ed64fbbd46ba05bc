#pragma once

namespace whiskermap::cli
{
/** The whisker-slam command line: tactile SLAM on a rawlog with MRPT's Rao-Blackwellised
 *  particle filter (slam::RbpfSlam), a CHierarchicalObjectMap per particle. Writes the
 *  estimated and odometry paths, the best particle's map in every format whisker-map writes,
 *  a picture of the paths over the map and a summary (doc/slam.md). */
struct WhiskerSlamApp
{
	static int main(int argc, char** argv);
};
}  // namespace whiskermap::cli
