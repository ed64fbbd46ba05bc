// Reads a rawlog with the installed whiskermap and prints its sweep and shapelet counts.
#include <whiskermap/obs/RawlogReader.h>

#include <iostream>

int main(int argc, char** argv)
{
	if (argc != 2) return 2;
	const auto c = whiskermap::obs::RawlogReader::read(argv[1]);
	size_t shapelets = 0;
	for (const auto& s : c.sweeps) shapelets += s.obs->toShapelets(s.robotPose).size();
	std::cout << "sweeps=" << c.sweeps.size() << " shapelets=" << shapelets << "\n";
	return 0;
}
