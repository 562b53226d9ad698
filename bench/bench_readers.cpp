// Read throughput of the importers, in MB/s of file, from files on disk (the page cache, after the
// first iteration): delimited text, an Xsens MT Manager text export, and an .mtb log.
#include "io/Import.h"
#include "sim/WalkSimulator.h"
#include "xbus/MtData2.h"
#include "xbus/XbusFrame.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <fstream>
#include <string>

using namespace footpath;

namespace {

constexpr int kLaps = 12;  // about 500 000 samples at 100 Hz

const std::vector<ImuSample>& walkSamples()
{
    static const std::vector<ImuSample> samples = [] {
        WalkSimulatorConfig config;
        config.accNoiseStd_mps2 = 0.01;
        config.gyrNoiseStd_radps = 0.0015;
        config.withMagnetometer = true;
        std::vector<Eigen::Vector3d> path{Eigen::Vector3d::Zero()};
        const std::vector<Eigen::Vector3d> lap = closedRectanglePath(200.0, 150.0);
        for (int i = 0; i < kLaps; ++i)
            path.insert(path.end(), lap.begin() + 1, lap.end());
        return simulateWalk(path, config).recording.samples;
    }();
    return samples;
}

std::string temporaryPath(const char* name)
{
    return std::string(P_tmpdir) + "/footpath-bench-" + name;
}

const std::string& delimitedFile()
{
    static const std::string path = [] {
        const std::string file = temporaryPath("walk.csv");
        std::FILE* out = std::fopen(file.c_str(), "w");
        std::fprintf(out, "time_s,acc_x,acc_y,acc_z,gyr_x,gyr_y,gyr_z,mag_x,mag_y,mag_z\n");
        for (const ImuSample& s : walkSamples())
            std::fprintf(out, "%.4f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.5f,%.5f,%.5f\n", s.time_s, s.acc_mps2.x(),
                         s.acc_mps2.y(), s.acc_mps2.z(), s.gyr_radps.x(), s.gyr_radps.y(), s.gyr_radps.z(), s.mag.x(),
                         s.mag.y(), s.mag.z());
        std::fclose(out);
        return file;
    }();
    return path;
}

const std::string& xsensTextFile()
{
    static const std::string path = [] {
        const std::string file = temporaryPath("walk.txt");
        std::FILE* out = std::fopen(file.c_str(), "w");
        std::fprintf(out, "// Start Time: Unknown\n// Update Rate: 100.0Hz\n// Filter Profile: human (46.1)\n"
                          "// Firmware Version: 4.0.2\n");
        std::fprintf(out, "PacketCounter\tSampleTimeFine\tAcc_X\tAcc_Y\tAcc_Z\tGyr_X\tGyr_Y\tGyr_Z\tMag_X\tMag_Y\tMag_Z\n");
        std::uint32_t k = 0;
        for (const ImuSample& s : walkSamples()) {
            std::fprintf(out, "%u\t%u\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%.6f\t%.5f\t%.5f\t%.5f\n", k % 65536u, k * 100u,
                         s.acc_mps2.x(), s.acc_mps2.y(), s.acc_mps2.z(), s.gyr_radps.x(), s.gyr_radps.y(),
                         s.gyr_radps.z(), s.mag.x(), s.mag.y(), s.mag.z());
            ++k;
        }
        std::fclose(out);
        return file;
    }();
    return path;
}

const std::string& mtbFile()
{
    static const std::string path = [] {
        const std::string file = temporaryPath("walk.mtb");
        std::ofstream out(file, std::ios::binary);
        std::uint32_t k = 0;
        for (const ImuSample& s : walkSamples()) {
            MtData2Sample sample;
            sample.packetCounter = static_cast<std::uint16_t>(k % 65536u);
            sample.sampleTimeFine = k * 100u;
            sample.acceleration = s.acc_mps2;
            sample.rateOfTurn = s.gyr_radps;
            sample.magneticField = s.mag;
            const std::vector<std::uint8_t> frame = encodeFrame({kXbusMasterBusId, XbusMid::MtData2, encodeMtData2(sample)});
            out.write(reinterpret_cast<const char*>(frame.data()), static_cast<std::streamsize>(frame.size()));
            ++k;
        }
        return file;
    }();
    return path;
}

void readFile(benchmark::State& state, const std::string& path)
{
    std::ifstream probe(path, std::ios::binary | std::ios::ate);
    const auto bytes = static_cast<std::int64_t>(probe.tellg());
    std::size_t samples = 0;
    for (auto _ : state) {
        const ImportResult read = importRecording(path);
        if (!read.ok())
            state.SkipWithError(read.error->text().c_str());
        samples = read.recording.samples.size();
        benchmark::DoNotOptimize(read.recording.samples.data());
    }
    state.SetBytesProcessed(state.iterations() * bytes);
    state.counters["samples"] = static_cast<double>(samples);
    state.counters["file_MB"] = static_cast<double>(bytes) / 1e6;
}

void BM_ReadDelimitedText(benchmark::State& state) { readFile(state, delimitedFile()); }
void BM_ReadXsensText(benchmark::State& state) { readFile(state, xsensTextFile()); }
void BM_ReadMtb(benchmark::State& state) { readFile(state, mtbFile()); }

BENCHMARK(BM_ReadDelimitedText)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadXsensText)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadMtb)->Unit(benchmark::kMillisecond);

}  // namespace

// main: BenchmarkMain.cpp
