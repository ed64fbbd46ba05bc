// Without libFuzzer (an ordinary build), a fuzz target is this driver: it runs the target
// on every file of the corpus folders given, so the seed corpora are regression tests.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

int main(int argc, char** argv)
{
	size_t n = 0;
	for (int i = 1; i < argc; i++)
	{
		if (argv[i][0] == '-') continue;  // libFuzzer options
		for (const auto& e : std::filesystem::directory_iterator(argv[i]))
		{
			std::ifstream f(e.path(), std::ios::binary);
			const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
			LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
			n++;
		}
	}
	std::printf("replayed %zu inputs\n", n);
	return n ? 0 : 1;
}
