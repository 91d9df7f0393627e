// OMPL's RRT* on one world of scripts/ompl_bench/make_worlds.py, for the comparison with
// tidepath's rrt-star (scripts/ompl_bench/run.sh, docs/ompl-benchmark.md).
//
// Native C++ throughout (no Python callbacks): a 2-D RealVectorStateSpace over the world's
// bounds, a validity checker that tests the point against every disc, OMPL's default discrete
// motion validator at a fixed resolution in metres, RRTstar with its defaults except the range,
// the path-length objective, and a goal state with a tiny threshold. The planner runs exactly
// N iterations (IterationTerminationCondition), and only planner->solve() is timed.
//
//   ompl_rrtstar WORLD.txt --seed S [--iterations 10000] [--range 1000] [--resolution 25]
//                [--goal-threshold 1e-6] [--k-nearest 1|0] [--name NAME] [--path-out PATH.json]
//                [--header]
//
// --k-nearest 1 (OMPL's default) rewires among the k = ceil(rewire_factor (e + e/d) log n)
// nearest vertices; 0 among those within r = min(range, gamma (log n / n)^(1/d)), the radius
// form of Karaman & Frazzoli that tidepath's rrt-star uses.
//
// Prints one CSV line:
//   world,seed,iterations,time_s,length,solved,exact,tree_states,state_checks
// and, with --path-out, writes the solution as {"waypoints": [[x, y, 0], ...]}, the minimal
// plan JSON that `tidepath eval WORLD.toml PATH.json` reads.

#include <ompl/base/Planner.h>
#include <ompl/base/PlannerData.h>
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/base/terminationconditions/IterationTerminationCondition.h>
#include <ompl/geometric/PathGeometric.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;

struct Circle
{
    double cx, cy, r2;
};

struct World
{
    double xmin, ymin, xmax, ymax, sx, sy, gx, gy;
    std::vector<Circle> circles;
};

static World readWorld(const std::string &path)
{
    std::ifstream in(path);
    if (!in)
    {
        std::cerr << "cannot read " << path << "\n";
        std::exit(2);
    }
    World w{};
    bool haveHead = false;
    std::string line;
    while (std::getline(in, line))
    {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream ls(line);
        if (!haveHead)
        {
            if (!(ls >> w.xmin >> w.ymin >> w.xmax >> w.ymax >> w.sx >> w.sy >> w.gx >> w.gy))
            {
                std::cerr << path << ": bad first line: " << line << "\n";
                std::exit(2);
            }
            haveHead = true;
            continue;
        }
        double cx, cy, r;
        if (!(ls >> cx >> cy >> r))
        {
            std::cerr << path << ": bad circle line: " << line << "\n";
            std::exit(2);
        }
        w.circles.push_back({cx, cy, r * r});
    }
    if (!haveHead)
    {
        std::cerr << path << ": no bounds line\n";
        std::exit(2);
    }
    return w;
}

// Valid: strictly outside every disc (a point on a circle touches it, as in tidepath with a
// safety distance of 0). Counts its calls, a plain integer: one thread.
class DiscValidityChecker : public ob::StateValidityChecker
{
public:
    DiscValidityChecker(const ob::SpaceInformationPtr &si, const World &world)
      : ob::StateValidityChecker(si), circles_(world.circles)
    {
    }

    bool isValid(const ob::State *state) const override
    {
        ++calls;
        const double *q = state->as<ob::RealVectorStateSpace::StateType>()->values;
        for (const Circle &c : circles_)
        {
            const double dx = q[0] - c.cx, dy = q[1] - c.cy;
            if (dx * dx + dy * dy <= c.r2)
                return false;
        }
        return true;
    }

    mutable unsigned long long calls = 0;

private:
    std::vector<Circle> circles_;
};

static void usage()
{
    std::cerr << "usage: ompl_rrtstar WORLD.txt --seed S [--iterations N] [--range M] [--resolution M]\n"
                 "                    [--goal-threshold M] [--k-nearest 1|0] [--name NAME] [--path-out FILE.json]\n"
                 "                    [--header]\n";
    std::exit(2);
}

int main(int argc, char **argv)
{
    std::string worldPath, name, pathOut;
    unsigned long seed = 0;
    bool haveSeed = false, header = false, kNearest = true;
    unsigned int iterations = 10000;
    double range = 1000.0, resolution = 25.0, goalThreshold = 1e-6;
    for (int i = 1; i < argc; ++i)
    {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc)
                usage();
            return argv[++i];
        };
        if (a == "--seed")
        {
            seed = std::stoul(value());
            haveSeed = true;
        }
        else if (a == "--iterations")
            iterations = static_cast<unsigned int>(std::stoul(value()));
        else if (a == "--range")
            range = std::stod(value());
        else if (a == "--resolution")
            resolution = std::stod(value());
        else if (a == "--goal-threshold")
            goalThreshold = std::stod(value());
        else if (a == "--k-nearest")
            kNearest = std::stoi(value()) != 0;
        else if (a == "--name")
            name = value();
        else if (a == "--path-out")
            pathOut = value();
        else if (a == "--header")
            header = true;
        else if (!a.empty() && a[0] == '-')
            usage();
        else
            worldPath = a;
    }
    if (worldPath.empty() || !haveSeed || seed == 0)
        usage();  // OMPL takes seed 0 as "no seed"
    if (name.empty())
        name = worldPath;

    // Before anything that owns a random number generator exists: every RNG made afterwards
    // (the planner's, the state sampler's) draws its seed from this one, so a seed reproduces a
    // run on the same OMPL build.
    ompl::RNG::setSeed(seed);
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);

    const World world = readWorld(worldPath);

    auto space = std::make_shared<ob::RealVectorStateSpace>(2);
    ob::RealVectorBounds bounds(2);
    bounds.setLow(0, world.xmin);
    bounds.setLow(1, world.ymin);
    bounds.setHigh(0, world.xmax);
    bounds.setHigh(1, world.ymax);
    space->setBounds(bounds);

    auto si = std::make_shared<ob::SpaceInformation>(space);
    auto checker = std::make_shared<DiscValidityChecker>(si, world);
    si->setStateValidityChecker(checker);
    // The default DiscreteMotionValidator tests states at most `resolution` metres apart.
    si->setStateValidityCheckingResolution(resolution / space->getMaximumExtent());
    si->setup();

    ob::ScopedState<> start(space), goal(space);
    start[0] = world.sx;
    start[1] = world.sy;
    goal[0] = world.gx;
    goal[1] = world.gy;

    auto pdef = std::make_shared<ob::ProblemDefinition>(si);
    pdef->setStartAndGoalStates(start, goal, goalThreshold);
    auto objective = std::make_shared<ob::PathLengthOptimizationObjective>(si);
    // A threshold no length reaches: RRT* never stops early for a "good enough" path.
    objective->setCostThreshold(ob::Cost(0.0));
    pdef->setOptimizationObjective(objective);

    auto planner = std::make_shared<og::RRTstar>(si);
    planner->setRange(range);  // goal bias (0.05), rewire factor (1.1), delayCC: defaults
    planner->setKNearest(kNearest);
    planner->setProblemDefinition(pdef);
    planner->setup();

    ob::IterationTerminationCondition iterationsLeft(iterations);
    const ob::PlannerTerminationCondition ptc = iterationsLeft;
    checker->calls = 0;

    const auto t0 = std::chrono::steady_clock::now();
    const ob::PlannerStatus status = planner->solve(ptc);
    const auto t1 = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(t1 - t0).count();

    const bool solved = static_cast<bool>(status);
    const bool exact = status == ob::PlannerStatus::EXACT_SOLUTION;
    double length = std::numeric_limits<double>::quiet_NaN();
    std::vector<std::pair<double, double>> waypoints;
    if (solved && pdef->getSolutionPath())
    {
        auto *path = pdef->getSolutionPath()->as<og::PathGeometric>();
        length = path->length();
        for (std::size_t i = 0; i < path->getStateCount(); ++i)
        {
            const double *q = path->getState(i)->as<ob::RealVectorStateSpace::StateType>()->values;
            waypoints.emplace_back(q[0], q[1]);
        }
    }
    ob::PlannerData data(si);
    planner->getPlannerData(data);

    if (!pathOut.empty())
    {
        std::FILE *f = std::fopen(pathOut.c_str(), "w");
        if (!f)
        {
            std::cerr << "cannot write " << pathOut << "\n";
            return 2;
        }
        std::fprintf(f, "{\"planner\": \"ompl-RRTstar\", \"seed\": %lu, \"waypoints\": [", seed);
        for (std::size_t i = 0; i < waypoints.size(); ++i)
            std::fprintf(f, "%s[%.17g, %.17g, 0.0]", i ? ", " : "", waypoints[i].first, waypoints[i].second);
        std::fprintf(f, "]}\n");
        std::fclose(f);
    }

    if (header)
        std::printf("world,seed,iterations,time_s,length,solved,exact,tree_states,state_checks\n");
    std::printf("%s,%lu,%u,%.6f,%.6f,%d,%d,%u,%llu\n", name.c_str(), seed, planner->numIterations(), seconds, length,
                solved ? 1 : 0, exact ? 1 : 0, data.numVertices(), checker->calls);
    return 0;
}
