#pragma once

#include <cstddef>
#include <istream>
#include <string>
#include <vector>

namespace footpath {

/// The longest line a text reader takes: far beyond any row of samples or header (a thousand
/// columns of long names), small enough that a file without line breaks (binary, or one 100 MB
/// line) is refused after reading this much instead of being held whole.
constexpr std::size_t kMaxTextLineLength_bytes = 1024 * 1024;

/// Reads text lines through a fixed buffer, so that no line grows beyond a bound, and remembers
/// whether the last line ended with a newline (a file cut in the middle of a line does not).
/// "\r\n" and "\n" both end a line.
class LineReader {
public:
    explicit LineReader(std::istream& in, std::size_t maxLength_bytes = kMaxTextLineLength_bytes);

    /// The next line without its line break. False at the end of the input, and from the call
    /// after a line reached the bound (overlong() then says so: reading stopped there).
    bool next(std::string& line);
    std::size_t lineNumber() const { return lineNumber_; }  ///< 1-based number of the last line
    std::size_t bytesRead() const { return bytesRead_; }    ///< through the end of the last line
    bool terminated() const { return terminated_; }
    /// The last line reached maxLength() bytes without a line break; it holds the first maxLength().
    bool overlong() const { return overlong_; }
    std::size_t maxLength() const { return maxLength_; }
    /// "the line is longer than 1 MiB (1048576 bytes), the most a line of text may hold": for the
    /// reader's error (which names the file and the line) when overlong().
    std::string overlongMessage() const;

private:
    bool fill();

    std::istream& in_;
    std::size_t maxLength_;
    std::vector<char> buffer_;
    std::size_t begin_ = 0;  ///< unread bytes are buffer_[begin_, end_)
    std::size_t end_ = 0;
    std::size_t lineNumber_ = 0;
    std::size_t bytesRead_ = 0;
    bool terminated_ = false;
    bool overlong_ = false;
};

}  // namespace footpath
