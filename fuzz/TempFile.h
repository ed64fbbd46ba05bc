#pragma once
// The file-based loaders are fuzzed through their real entry points: each input is written
// to one temporary file (in /dev/shm when there is one) that the loader then reads.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>

inline const std::string& fuzzFile(const uint8_t* data, size_t size, const char* suffix)
{
	static const std::string path = std::string(access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") +
									"/whiskermap_fuzz_" + std::to_string(getpid()) + suffix;
	FILE* f = std::fopen(path.c_str(), "wb");
	if (size) std::fwrite(data, 1, size, f);
	std::fclose(f);
	return path;
}
