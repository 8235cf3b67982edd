// Runs a case through soilcut's C API from C++, with a RAII wrapper that
// frees the handle in its destructor and turns every error status into an
// exception:
//
//     run CASE.toml [KEY=VALUE ...]
//
// prints the history as crates/ffi/examples/c/run.c does (history.csv's
// header, then one row per increment with %.17g numbers). Half way it
// takes a snapshot; at the end it restores it, runs the second half again
// and checks that the forces repeat bit for bit. Exit status 2 on bad
// input, 1 on any other error.
//
// Build (README.md, "C and C++"; the rpath is absolute, so that the binary
// finds the library from any folder):
//     cargo build --release -p soilcut-ffi
//     c++ -std=c++17 -I crates/ffi/include crates/ffi/examples/cpp/run.cpp
//         -L target/release -lsoilcut_ffi -Wl,-rpath,"$PWD/target/release" -o target/run-cpp
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "soilcut.h"

namespace soilcut {

// A failed call: its status code (SOILCUT_ERR_*) and message.
class Error : public std::runtime_error {
public:
    Error(int code, const std::string &message) : std::runtime_error(message), code_(code) {}
    int code() const { return code_; }

private:
    int code_;
};

// The message of the last failed call on `sim` (nullptr: of this thread).
inline std::string last_error(const SoilcutSimulation *sim)
{
    std::string message(soilcut_last_error(sim, nullptr, 0), '\0');
    soilcut_last_error(sim, &message[0], message.size());
    message.pop_back(); // the NUL
    return message;
}

// One simulation; owns its handle (movable, not copyable).
class Simulation {
public:
    static Simulation from_file(const std::string &path, const std::vector<std::string> &sets = {})
    {
        std::vector<const char *> pointers;
        for (const auto &set : sets) {
            pointers.push_back(set.c_str());
        }
        SoilcutSimulation *sim = nullptr;
        check_new(soilcut_new_from_file(path.c_str(), pointers.data(), pointers.size(), &sim));
        return Simulation(sim);
    }

    static Simulation restore(const std::vector<std::uint8_t> &bytes)
    {
        SoilcutSimulation *sim = nullptr;
        check_new(soilcut_restore(bytes.data(), bytes.size(), &sim));
        return Simulation(sim);
    }

    Simulation(Simulation &&other) noexcept : sim_(std::exchange(other.sim_, nullptr)) {}
    Simulation &operator=(Simulation &&other) noexcept
    {
        std::swap(sim_, other.sim_);
        return *this;
    }
    Simulation(const Simulation &) = delete;
    Simulation &operator=(const Simulation &) = delete;
    ~Simulation() { soilcut_free(sim_); }

    SoilcutStep step()
    {
        SoilcutStep record;
        check(soilcut_step(sim_, &record));
        return record;
    }

    SoilcutState state() const
    {
        SoilcutState state;
        check(soilcut_state(sim_, &state));
        return state;
    }

    bool done() const { return state().done != 0; }

    std::vector<std::uint8_t> snapshot() const
    {
        std::size_t needed = 0;
        check(soilcut_snapshot(sim_, nullptr, 0, &needed));
        std::vector<std::uint8_t> bytes(needed);
        check(soilcut_snapshot(sim_, bytes.data(), bytes.size(), &needed));
        return bytes;
    }

    // The surface's x and y (length).
    std::pair<std::vector<double>, std::vector<double>> surface() const
    {
        std::size_t n = 0;
        check(soilcut_surface_len(sim_, &n));
        std::vector<double> x(n), y(n);
        check(soilcut_surface(sim_, x.data(), y.data(), nullptr, nullptr, nullptr, n));
        return {std::move(x), std::move(y)};
    }

private:
    explicit Simulation(SoilcutSimulation *sim) : sim_(sim) {}

    static void check_new(int code)
    {
        if (code != SOILCUT_OK) {
            throw Error(code, last_error(nullptr));
        }
    }

    void check(int code) const
    {
        if (code != SOILCUT_OK) {
            throw Error(code, last_error(sim_));
        }
    }

    SoilcutSimulation *sim_;
};

} // namespace soilcut

static void print_row(const SoilcutStep &r)
{
    std::printf("%" PRIu64
                ",%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                r.step, r.u, r.u_over_d, r.force, r.force_norm, r.force_h, r.force_v, r.beta_deg,
                r.x_emergence, r.mass, r.y_emergence, r.friction_deg, r.slip, r.dilation_deg,
                r.dilation_area, r.depth, r.mass_spilled, r.weight, r.force_factor,
                r.face_friction_deg, r.moment, r.tool_x, r.tool_y, r.tool_rotation);
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s CASE.toml [KEY=VALUE ...]\n", argv[0]);
        return 2;
    }
    try {
        auto sim = soilcut::Simulation::from_file(argv[1], std::vector<std::string>(argv + 2, argv + argc));
        const std::uint64_t half = sim.state().steps_total / 2;
        std::vector<std::uint8_t> snapshot;
        std::vector<SoilcutStep> second_half;
        std::printf("%s\n", soilcut_history_header());
        while (!sim.done()) {
            if (sim.state().steps_done == half) {
                snapshot = sim.snapshot();
            }
            const SoilcutStep record = sim.step();
            if (record.step > half) {
                second_half.push_back(record);
            }
            print_row(record);
        }
        auto again = soilcut::Simulation::restore(snapshot);
        for (const SoilcutStep &want : second_half) {
            const SoilcutStep got = again.step();
            if (std::memcmp(&got.force, &want.force, sizeof got.force) != 0 || got.step != want.step) {
                std::fprintf(stderr, "error: the restored run differs at increment %" PRIu64 "\n", want.step);
                return 1;
            }
        }
        const auto surface = sim.surface();
        std::fprintf(stderr, "restored at increment %" PRIu64 ": %zu increments repeat bit for bit; final surface: %zu points\n",
                     half, second_half.size(), surface.first.size());
    } catch (const soilcut::Error &e) {
        // The constructor's message names the file already.
        const std::string file = std::string(argv[1]) + ": ";
        if (std::strncmp(e.what(), file.c_str(), file.size()) == 0) {
            std::fprintf(stderr, "error: %s\n", e.what());
        } else {
            std::fprintf(stderr, "error: %s: %s\n", argv[1], e.what());
        }
        return e.code() == SOILCUT_ERR_INPUT || e.code() == SOILCUT_ERR_STEP ? 2 : 1;
    }
    return 0;
}
