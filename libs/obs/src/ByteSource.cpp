#include <whiskermap/core/Error.h>
#include <whiskermap/obs/ByteSource.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <filesystem>

namespace whiskermap::obs
{
namespace
{
class GzFileSource : public ByteSource
{
   public:
	explicit GzFileSource(const std::string& path) : m_path(path), m_file(gzopen(path.c_str(), "rb"))
	{
		if (!m_file) throw core::Error(path + ": cannot open file");
	}
	~GzFileSource() override { gzclose(m_file); }
	GzFileSource(const GzFileSource&) = delete;
	GzFileSource& operator=(const GzFileSource&) = delete;

	size_t read(uint8_t* dst, size_t n) override
	{
		size_t got = 0;
		while (got < n)
		{
			const int r = gzread(m_file, dst + got, static_cast<unsigned>(std::min<size_t>(n - got, INT_MAX / 2)));
			if (r < 0) fail();
			if (r == 0) break;
			got += static_cast<size_t>(r);
		}
		if (got < n) checkCleanEnd();
		return got;
	}

   private:
	/** At the end of the data: a gzip stream cut off reads as a short stream (Z_BUF_ERROR). */
	void checkCleanEnd()
	{
		int err = Z_OK;
		gzerror(m_file, &err);
		if (err != Z_OK) fail();
	}
	[[noreturn]] void fail()
	{
		int err = Z_OK;
		std::string msg = gzerror(m_file, &err);
		if (msg.rfind(m_path + ": ", 0) == 0) msg = msg.substr(m_path.size() + 2);
		throw core::Error(m_path + ": truncated or corrupt gzip data (" + msg + ")");
	}
	std::string m_path;
	gzFile m_file;
};

class MemorySource : public ByteSource
{
   public:
	MemorySource(const uint8_t* data, size_t size) : m_data(data), m_size(size) {}
	size_t read(uint8_t* dst, size_t n) override
	{
		n = std::min(n, m_size - m_pos);
		if (n) std::memcpy(dst, m_data + m_pos, n);
		m_pos += n;
		return n;
	}

   private:
	const uint8_t* m_data;
	size_t m_size, m_pos = 0;
};
}  // namespace

std::unique_ptr<ByteSource> ByteSource::file(const std::string& path)
{
	std::error_code ec;
	if (!std::filesystem::exists(path, ec)) throw core::Error(path + ": no such file");
	if (std::filesystem::is_directory(path, ec)) throw core::Error(path + ": is a directory, not a rawlog");
	if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) == 0)
		throw core::Error(path + ": empty file, not a rawlog");
	return std::make_unique<GzFileSource>(path);
}

std::unique_ptr<ByteSource> ByteSource::memory(const uint8_t* data, size_t size)
{
	return std::make_unique<MemorySource>(data, size);
}
}  // namespace whiskermap::obs
