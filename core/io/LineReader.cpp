#include "io/LineReader.h"

#include <algorithm>
#include <cstring>

namespace footpath {

namespace {

constexpr std::size_t kBufferSize = 64 * 1024;

std::string byteSize(std::size_t bytes)
{
    if (bytes >= 1024 * 1024 && bytes % (1024 * 1024) == 0)
        return std::to_string(bytes / (1024 * 1024)) + " MiB (" + std::to_string(bytes) + " bytes)";
    if (bytes >= 1024 && bytes % 1024 == 0)
        return std::to_string(bytes / 1024) + " KiB (" + std::to_string(bytes) + " bytes)";
    return std::to_string(bytes) + " bytes";
}

}  // namespace

LineReader::LineReader(std::istream& in, std::size_t maxLength_bytes)
    : in_(in), maxLength_(std::max<std::size_t>(1, maxLength_bytes)), buffer_(kBufferSize)
{
}

bool LineReader::fill()
{
    if (!in_)
        return false;
    in_.read(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    begin_ = 0;
    end_ = static_cast<std::size_t>(std::max<std::streamsize>(0, in_.gcount()));
    return end_ > 0;
}

bool LineReader::next(std::string& line)
{
    line.clear();
    terminated_ = false;
    if (overlong_)
        return false;
    bool sawBytes = false;
    while (begin_ < end_ || fill()) {
        sawBytes = true;
        const char* start = buffer_.data() + begin_;
        const std::size_t available = end_ - begin_;
        const auto* lineBreak = static_cast<const char*>(std::memchr(start, '\n', available));
        const std::size_t length = lineBreak != nullptr ? static_cast<std::size_t>(lineBreak - start) : available;
        const std::size_t taken = std::min(length, maxLength_ - line.size());
        line.append(start, taken);
        begin_ += taken;
        bytesRead_ += taken;
        if (taken < length) {
            overlong_ = true;  // the rest of this line (and of the file) is never read
            break;
        }
        if (lineBreak != nullptr) {
            ++begin_;
            ++bytesRead_;
            terminated_ = true;
            break;
        }
    }
    if (!sawBytes)
        return false;
    ++lineNumber_;
    if (!overlong_ && !line.empty() && line.back() == '\r')
        line.pop_back();
    return true;
}

std::string LineReader::overlongMessage() const
{
    return "the line is longer than " + byteSize(maxLength_) + ", the most a line of text may hold";
}

}  // namespace footpath
