// Writes a simulated walk of a given length in time as a CSV file that footpath-cli reads: for
// measuring time and memory on long recordings (a 10-hour walk) without keeping such files around.
//
//   simulate_walk_csv HOURS RATE_HZ OUT.csv
//
// Laps of a 200 m x 150 m rectangle walked by an MTi-class sensor (noise and biases of its data
// sheet), the whole number of laps nearest the hours (10: 65 laps, 9.93 h), with the simulator's
// rest at the start and the end.
#include "sim/WalkSimulator.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace footpath;

namespace {

constexpr double kLapLength_m = 700.0;

bool writeCsv(const Recording& recording, const char* path)
{
    std::FILE* out = std::fopen(path, "w");
    if (out == nullptr)
        return false;
    std::fprintf(out, "time_s,acc_x_mps2,acc_y_mps2,acc_z_mps2,gyr_x_radps,gyr_y_radps,gyr_z_radps\n");
    for (const ImuSample& s : recording.samples)
        std::fprintf(out, "%.5f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f\n", s.time_s, s.acc_mps2.x(), s.acc_mps2.y(),
                     s.acc_mps2.z(), s.gyr_radps.x(), s.gyr_radps.y(), s.gyr_radps.z());
    return std::fclose(out) == 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s HOURS RATE_HZ OUT.csv\n", argv[0]);
        return 2;
    }
    const double hours = std::atof(argv[1]);
    const double rate_hz = std::atof(argv[2]);
    if (!(hours > 0.0 && hours <= 100.0) || !(rate_hz >= 10.0 && rate_hz <= 2000.0)) {
        std::fprintf(stderr, "HOURS must be in (0, 100] and RATE_HZ in [10, 2000]\n");
        return 2;
    }
    const WalkSimulatorConfig config = mtiClassSensor(rate_hz);
    const double lapDuration_s = kLapLength_m / config.strideLength_m * (config.stanceDuration_s + config.swingDuration_s);
    const int laps = std::max(1, static_cast<int>(std::lround(hours * 3600.0 / lapDuration_s)));
    std::vector<Eigen::Vector3d> path{Eigen::Vector3d::Zero()};
    const std::vector<Eigen::Vector3d> lap = closedRectanglePath(200.0, 150.0);
    for (int i = 0; i < laps; ++i)
        path.insert(path.end(), lap.begin() + 1, lap.end());
    const Recording recording = simulateWalk(path, config).recording;
    if (!writeCsv(recording, argv[3])) {
        std::fprintf(stderr, "%s: cannot write the file\n", argv[3]);
        return 1;
    }
    std::printf("%zu samples, %.2f h, %d laps of %.0f m\n", recording.samples.size(), recording.duration_s() / 3600.0,
                laps, kLapLength_m);
    return 0;
}
