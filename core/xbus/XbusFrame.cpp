#include "xbus/XbusFrame.h"

#include <algorithm>

namespace footpath {

namespace {

std::uint8_t byteSum(const std::uint8_t* data, std::size_t size)
{
    std::uint32_t sum = 0;
    for (std::size_t i = 0; i < size; ++i)
        sum += data[i];
    return static_cast<std::uint8_t>(sum & 0xFFu);
}

}  // namespace

void appendBigEndian(std::vector<std::uint8_t>& out, std::uint64_t value, std::size_t byteCount)
{
    for (std::size_t i = byteCount; i-- > 0;)
        out.push_back(static_cast<std::uint8_t>((value >> (8 * i)) & 0xFFu));
}

std::vector<std::uint8_t> encodeFrame(const XbusMessage& message)
{
    const std::size_t size = message.payload.size();
    if (size > kXbusMaxPayload)
        return {};
    std::vector<std::uint8_t> frame;
    frame.reserve(size + 7);
    frame.push_back(kXbusPreamble);
    frame.push_back(message.busId);
    frame.push_back(message.mid);
    if (size <= kXbusMaxStandardPayload) {
        frame.push_back(static_cast<std::uint8_t>(size));
    } else {
        frame.push_back(kXbusExtendedLength);
        appendBigEndian(frame, size, 2);
    }
    frame.insert(frame.end(), message.payload.begin(), message.payload.end());
    // The preamble is not summed; the extended-length marker and both length bytes are (§8.6).
    const std::uint8_t sum = byteSum(frame.data() + 1, frame.size() - 1);
    frame.push_back(static_cast<std::uint8_t>((0x100u - sum) & 0xFFu));
    return frame;
}

XbusFrameDecoder::XbusFrameDecoder(std::size_t bufferLimit)
    : bufferLimit_(std::max(bufferLimit, kXbusMaxFrameSize))
{
}

void XbusFrameDecoder::reset()
{
    buffer_.clear();
    head_ = 0;
    headOffset_ = 0;
    lastFrameOffset_ = 0;
    finished_ = false;
    stats_ = {};
    openSkipRun_ = SIZE_MAX;
    skipRunEnd_ = UINT64_MAX;
    damagedUntil_ = 0;
}

void XbusFrameDecoder::feed(const std::uint8_t* data, std::size_t size)
{
    if (size == 0)
        return;
    finished_ = false;
    compact();
    buffer_.insert(buffer_.end(), data, data + size);
    if (pendingBytes() <= bufferLimit_)
        return;
    // A consumer that stopped calling next() must not make the buffer grow without end; the
    // oldest bytes go, like a serial driver whose reader stalls.
    const std::size_t excess = pendingBytes() - bufferLimit_;
    recordProblem(XbusStreamProblem::Kind::Overflow, headOffset_, excess);
    stats_.bytesDroppedOverflow += excess;
    head_ += excess;
    headOffset_ += excess;
}

void XbusFrameDecoder::finish()
{
    finished_ = true;
}

void XbusFrameDecoder::compact()
{
    // Erasing the consumed prefix only once it is at least half the buffer keeps feed() amortised O(n).
    if (head_ > 0 && head_ >= buffer_.size() / 2) {
        buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(head_));
        head_ = 0;
    }
}

bool XbusFrameDecoder::next(XbusMessage& out)
{
    for (;;) {
        skipToPreamble();
        if (pendingBytes() == 0)
            return false;
        FrameExtent extent;
        switch (checkCandidate(head_, extent)) {
        case Candidate::Valid:
            takeFrame(extent, out);
            return true;
        case Candidate::NeedMore:
            if (!finished_)
                return false;
            // A false preamble: a valid frame follows, or it lies inside a damaged frame.
            if (headOffset_ < damagedUntil_ || validFrameFollows(head_ + 1)) {
                dropBytes(1);
                break;
            }
            recordProblem(XbusStreamProblem::Kind::Truncated, headOffset_, pendingBytes());
            stats_.bytesTruncated += pendingBytes();
            headOffset_ += pendingBytes();
            head_ = buffer_.size();
            return false;
        case Candidate::BadChecksum:
            recordBadChecksum(extent);
            dropBytes(1);
            break;
        case Candidate::NotAFrame:
            dropBytes(1);
            break;
        }
    }
}

XbusFrameDecoder::Candidate XbusFrameDecoder::checkCandidate(std::size_t position, FrameExtent& extent) const
{
    const std::size_t available = buffer_.size() - position;
    if (available < 4)
        return Candidate::NeedMore;
    const std::uint8_t* frame = buffer_.data() + position;
    if (frame[1] == 0x00 && frame[2] == 0x00)  // FA 00 00 00 00 would pass the checksum (§1.4)
        return Candidate::NotAFrame;
    extent = {4, frame[3]};
    if (frame[3] == kXbusExtendedLength) {
        if (available < 6)
            return Candidate::NeedMore;
        extent = {6, static_cast<std::size_t>(frame[4]) << 8 | frame[5]};
        if (extent.payloadSize > kXbusMaxPayload)  // a corrupt length must not stall the stream
            return Candidate::NotAFrame;
    }
    if (available < extent.frameSize())
        return Candidate::NeedMore;
    return byteSum(frame + 1, extent.frameSize() - 1) == 0 ? Candidate::Valid : Candidate::BadChecksum;
}

bool XbusFrameDecoder::validFrameFollows(std::size_t position) const
{
    for (std::size_t at = position; at < buffer_.size(); ++at) {
        FrameExtent extent;
        if (buffer_[at] == kXbusPreamble && checkCandidate(at, extent) == Candidate::Valid)
            return true;
    }
    return false;
}

void XbusFrameDecoder::skipToPreamble()
{
    const auto begin = buffer_.begin() + static_cast<std::ptrdiff_t>(head_);
    const auto preamble = std::find(begin, buffer_.end(), kXbusPreamble);
    const auto garbage = static_cast<std::size_t>(preamble - begin);
    if (garbage > 0)
        dropBytes(garbage);
}

void XbusFrameDecoder::dropBytes(std::size_t count)
{
    if (damagedUntil_ > headOffset_)
        stats_.damagedFrameBytes += std::min<std::uint64_t>(count, damagedUntil_ - headOffset_);
    recordSkipped(headOffset_, count);
    stats_.bytesSkipped += count;
    head_ += count;
    headOffset_ += count;
}

void XbusFrameDecoder::takeFrame(const FrameExtent& extent, XbusMessage& out)
{
    const std::uint8_t* frame = buffer_.data() + head_;
    out.busId = frame[1];
    out.mid = frame[2];
    out.payload.assign(frame + extent.headerSize, frame + extent.headerSize + extent.payloadSize);
    lastFrameOffset_ = headOffset_;
    damagedUntil_ = std::min(damagedUntil_, headOffset_);  // a damaged length claimed this frame's bytes
    head_ += extent.frameSize();
    headOffset_ += extent.frameSize();
    ++stats_.framesDecoded;
}

void XbusFrameDecoder::recordBadChecksum(const FrameExtent& extent)
{
    ++stats_.checksumFailures;
    recordProblem(XbusStreamProblem::Kind::BadChecksum, headOffset_, extent.frameSize());
    if (headOffset_ >= damagedUntil_) {
        ++stats_.damagedFrames;
        damagedUntil_ = headOffset_ + extent.frameSize();
    }
}

void XbusFrameDecoder::recordSkipped(std::uint64_t offset, std::uint64_t size)
{
    // Bytes skipped back to back (garbage, then a false preamble, ...) are one problem, not one each.
    if (offset == skipRunEnd_) {
        if (openSkipRun_ < stats_.firstProblems.size())
            stats_.firstProblems[openSkipRun_].size += size;
    } else {
        ++stats_.skippedRuns;
        const bool recorded = stats_.firstProblems.size() < XbusDecodeStats::kMaxRecordedProblems;
        recordProblem(XbusStreamProblem::Kind::SkippedBytes, offset, size);
        openSkipRun_ = recorded ? stats_.firstProblems.size() - 1 : SIZE_MAX;
    }
    skipRunEnd_ = offset + size;
}

void XbusFrameDecoder::recordProblem(XbusStreamProblem::Kind kind, std::uint64_t offset, std::uint64_t size)
{
    ++stats_.problemCount;
    if (stats_.firstProblems.size() < XbusDecodeStats::kMaxRecordedProblems)
        stats_.firstProblems.push_back({kind, offset, size});
}

// ---------------------------------------------------------------------------------------------

bool XbusPayloadReader::readUnsigned(std::size_t count, std::uint64_t& value)
{
    if (count > sizeof value || remaining() < count)
        return false;
    value = 0;
    for (std::size_t i = 0; i < count; ++i)
        value = value << 8 | data_[offset_ + i];
    offset_ += count;
    return true;
}

bool XbusPayloadReader::readU8(std::uint8_t& value)
{
    std::uint64_t raw = 0;
    if (!readUnsigned(1, raw))
        return false;
    value = static_cast<std::uint8_t>(raw);
    return true;
}

bool XbusPayloadReader::readU16(std::uint16_t& value)
{
    std::uint64_t raw = 0;
    if (!readUnsigned(2, raw))
        return false;
    value = static_cast<std::uint16_t>(raw);
    return true;
}

bool XbusPayloadReader::readU32(std::uint32_t& value)
{
    std::uint64_t raw = 0;
    if (!readUnsigned(4, raw))
        return false;
    value = static_cast<std::uint32_t>(raw);
    return true;
}

bool XbusPayloadReader::readU64(std::uint64_t& value)
{
    return readUnsigned(8, value);
}

bool XbusPayloadReader::skip(std::size_t count)
{
    if (remaining() < count)
        return false;
    offset_ += count;
    return true;
}

bool XbusPayloadReader::view(std::size_t count, const std::uint8_t*& bytes)
{
    if (remaining() < count)
        return false;
    bytes = data_ + offset_;
    offset_ += count;
    return true;
}

}  // namespace footpath
