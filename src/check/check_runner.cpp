// The check's runner in this process (check/check_runner.h): the page's, where there are no
// child processes.
#include "check/check_runner.h"

#include <chrono>
#include <stdexcept>

#include "check/check_snapshots.h"

namespace oasis {
namespace {

// The page's runner: the same calls in this process.
class InProcessRunner : public CaseRunner {
public:
    FrameRun frame(const std::vector<std::string>& arguments, bool gpuPlants) override {
        FrameRun run;
        const auto start = std::chrono::steady_clock::now();
        try {
            run.frame = renderCaseFrame(arguments, gpuPlants);
        } catch (const std::exception& error) {
            run.outcome.error = error.what();
        }
        run.outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return run;
    }
    PassesRun passes(const std::vector<std::string>& arguments, const std::vector<bool>& where, int, int) override {
        PassesRun run;
        try {
            run.snapshots = renderPassByPass(arguments);
            keepPixels(run.snapshots, where);
        } catch (const std::exception& error) {
            run.outcome.error = error.what();
        }
        return run;
    }
    DriverRun driver(const std::vector<std::string>& arguments) override {
        DriverRun run;
        try {
            run.driver = driverReport(arguments);
        } catch (const std::exception& error) {
            run.outcome.error = error.what();
        }
        return run;
    }
    std::string isolation() const override { return "the page itself (no processes: a tab that dies is the verdict)"; }
};

}  // namespace

std::unique_ptr<CaseRunner> makeInProcessRunner() { return std::make_unique<InProcessRunner>(); }

}  // namespace oasis
