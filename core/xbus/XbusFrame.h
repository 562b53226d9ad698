#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace footpath {

// Xbus framing (docs/xbus.md §1):
//   FA BID MID LEN DATA[LEN] CS            (LEN 0..254)
//   FA BID MID FF LENH LENL DATA[LEN] CS   (LEN >= 255, big-endian)
// CS makes the 8-bit sum of every byte after the preamble zero.
constexpr std::uint8_t kXbusPreamble = 0xFA;
constexpr std::uint8_t kXbusMasterBusId = 0xFF;     ///< the bus id of a single MTi on serial/USB
constexpr std::uint8_t kXbusExtendedLength = 0xFF;  ///< LEN value announcing a 2-byte length
constexpr std::size_t kXbusMaxStandardPayload = 254;
constexpr std::size_t kXbusMaxPayload = 8185;  ///< XSP's XS_MAXDATALEN; longer claims are corrupt
constexpr std::size_t kXbusMaxFrameSize = kXbusMaxPayload + 7;

/// Message identifiers the readers and the emulator use (§2).
namespace XbusMid {
constexpr std::uint8_t Configuration = 0x0D;
constexpr std::uint8_t GoToMeasurement = 0x10;
constexpr std::uint8_t GoToConfig = 0x30;
constexpr std::uint8_t MtData = 0x32;  ///< legacy fixed-layout data (§6)
constexpr std::uint8_t MtData2 = 0x36;
constexpr std::uint8_t WakeUp = 0x3E;
constexpr std::uint8_t Error = 0x42;
constexpr std::uint8_t EmtsData = 0x91;  ///< encrypted calibration blob, opaque
}  // namespace XbusMid

struct XbusMessage {
    std::uint8_t busId = kXbusMasterBusId;
    std::uint8_t mid = 0;
    std::vector<std::uint8_t> payload;
};

/// The complete frame for `message`: the standard form up to 254 payload bytes, the extended form
/// above. A payload longer than kXbusMaxPayload cannot be framed (no receiver would accept it):
/// the result is then empty.
std::vector<std::uint8_t> encodeFrame(const XbusMessage& message);

/// Something the decoder had to step over, at a byte offset counted from the first byte fed.
struct XbusStreamProblem {
    enum class Kind {
        SkippedBytes,  ///< a run of bytes that belongs to no valid frame (garbage, false preambles)
        BadChecksum,   ///< a complete candidate frame whose checksum did not add up
        Overflow,      ///< bytes dropped because the consumer did not drain the buffer in time
        Truncated,     ///< the stream ended inside a frame that started here
    };
    Kind kind = Kind::SkippedBytes;
    std::uint64_t offset = 0;
    std::uint64_t size = 0;  ///< bytes involved (claimed frame size for BadChecksum)
};

struct XbusDecodeStats {
    static constexpr std::size_t kMaxRecordedProblems = 16;

    std::uint64_t framesDecoded = 0;
    std::uint64_t bytesSkipped = 0;
    std::uint64_t skippedRuns = 0;  ///< separate stretches of skipped bytes
    std::uint64_t checksumFailures = 0;  ///< candidates that failed, false preambles inside a damaged frame too
    /// Frames that failed their checksum, each once: a bad candidate starting inside the claimed
    /// extent of the previous one is a false preamble in its bytes, not another frame. Exact
    /// unless the length byte itself was damaged (then nobody can tell where the frame ended).
    std::uint64_t damagedFrames = 0;
    std::uint64_t damagedFrameBytes = 0;  ///< skipped bytes inside those frames; the rest was junk
    std::uint64_t bytesDroppedOverflow = 0;
    std::uint64_t bytesTruncated = 0;  ///< bytes of an unfinished frame at the end of the stream
    std::uint64_t problemCount = 0;    ///< all problems, also those not recorded below
    std::vector<XbusStreamProblem> firstProblems;  ///< the first kMaxRecordedProblems, in the order found
};

/// Incremental Xbus frame decoder for files and serial ports: feed byte chunks of any size, then
/// call next() until it returns false. It resynchronises like XSP's protocol handler (§1.4): at
/// every 0xFA it tries a frame; a claimed length above kXbusMaxPayload, a BID 00 + MID 00 header
/// (a false hit inside zero runs) or a bad checksum drops that one byte and the scan goes on.
class XbusFrameDecoder {
public:
    static constexpr std::size_t kDefaultBufferLimit = std::size_t{1} << 20;

    /// `bufferLimit` bounds the bytes held between feed() and next(); it is raised to at least
    /// one maximal frame. Bytes beyond it are dropped (oldest first) and reported as Overflow.
    explicit XbusFrameDecoder(std::size_t bufferLimit = kDefaultBufferLimit);

    void feed(const std::uint8_t* data, std::size_t size);
    /// No more bytes will come: next() then resolves an unfinished frame at the end (Truncated).
    void finish();
    /// The next complete frame, or false when more bytes are needed (or, after finish(), at the end).
    bool next(XbusMessage& out);
    /// Forgets buffered bytes, statistics and offsets (for a reopened port).
    void reset();

    const XbusDecodeStats& stats() const { return stats_; }
    std::size_t pendingBytes() const { return buffer_.size() - head_; }
    std::uint64_t pendingOffset() const { return headOffset_; }       ///< offset of the first pending byte
    std::uint64_t lastFrameOffset() const { return lastFrameOffset_; }  ///< of the frame next() returned last

private:
    enum class Candidate { Valid, NeedMore, NotAFrame, BadChecksum };
    struct FrameExtent {
        std::size_t headerSize = 0;
        std::size_t payloadSize = 0;
        std::size_t frameSize() const { return headerSize + payloadSize + 1; }
    };

    Candidate checkCandidate(std::size_t position, FrameExtent& extent) const;
    bool validFrameFollows(std::size_t position) const;
    void skipToPreamble();
    void dropBytes(std::size_t count);
    void takeFrame(const FrameExtent& extent, XbusMessage& out);
    void compact();
    void recordProblem(XbusStreamProblem::Kind kind, std::uint64_t offset, std::uint64_t size);
    void recordSkipped(std::uint64_t offset, std::uint64_t size);
    void recordBadChecksum(const FrameExtent& extent);

    std::size_t bufferLimit_;
    std::vector<std::uint8_t> buffer_;
    std::size_t head_ = 0;            ///< first undecoded byte in buffer_
    std::uint64_t headOffset_ = 0;    ///< stream offset of buffer_[head_]
    std::uint64_t lastFrameOffset_ = 0;
    bool finished_ = false;
    XbusDecodeStats stats_;
    std::size_t openSkipRun_ = SIZE_MAX;     ///< index in firstProblems of the last skipped run
    std::uint64_t skipRunEnd_ = UINT64_MAX;  ///< offset just past the last skipped run
    std::uint64_t damagedUntil_ = 0;         ///< offset just past the claimed extent of the last damaged frame
};

/// Bounds-checked big-endian reader over a payload: every read says whether the bytes were there,
/// so a short or lying payload can never be read past its end.
class XbusPayloadReader {
public:
    XbusPayloadReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    std::size_t offset() const { return offset_; }
    std::size_t remaining() const { return size_ - offset_; }

    bool readU8(std::uint8_t& value);
    bool readU16(std::uint16_t& value);
    bool readU32(std::uint32_t& value);
    bool readU64(std::uint64_t& value);
    /// An unsigned big-endian integer of `byteCount` bytes (at most 8).
    bool readUnsigned(std::size_t byteCount, std::uint64_t& value);
    bool skip(std::size_t count);
    /// Points `bytes` at the next `count` bytes and moves past them.
    bool view(std::size_t count, const std::uint8_t*& bytes);

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t offset_ = 0;
};

/// Appends the low `byteCount` bytes of `value`, most significant first.
void appendBigEndian(std::vector<std::uint8_t>& out, std::uint64_t value, std::size_t byteCount);

}  // namespace footpath
