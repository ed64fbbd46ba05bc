#pragma once
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace whiskermap::obs
{
/** A stream of bytes read in order, for parsers that must not trust their input: a file
 *  (gzip-compressed or plain, both through zlib) or a memory buffer (tests, fuzzing).
 *  read() returns fewer bytes than asked only at the end of the data; a file whose gzip
 *  data is corrupt or cut off throws core::Error naming it. */
class ByteSource
{
   public:
	virtual ~ByteSource() = default;
	/** Up to n bytes into dst; 0 at the end. */
	virtual size_t read(uint8_t* dst, size_t n) = 0;

	/** Opens `path` (gzip or plain). Throws core::Error if it is missing, a directory,
	 *  empty or unreadable. */
	static std::unique_ptr<ByteSource> file(const std::string& path);
	/** Reads `size` bytes at `data` (not copied: they must outlive the source). */
	static std::unique_ptr<ByteSource> memory(const uint8_t* data, size_t size);
};
}  // namespace whiskermap::obs
