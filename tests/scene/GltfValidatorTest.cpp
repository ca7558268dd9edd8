// The loader judged against the Khronos glTF Validator (npm gltf-validator, scripts/gltf-validate.js): seeded
// mutants of the repository's own glTF scenes go through both; a file the validator rejects is refused, or loads
// with a note for each tolerated deviation, and a file it accepts loads (or is refused for a feature named as not
// supported).
#include "GltfAnimationScenes.hpp"
#include "GltfLoaderFixture.hpp"
#include "GltfMutations.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <set>

namespace penumbra::scene {
namespace {

struct Verdict {
    std::vector<std::string> codes; // the validator's error codes
    std::string errors; // "CODE at /pointer; ..."
};

// The validator's errors per file, from one node process for all of them.
std::map<std::string, Verdict> validate(const std::vector<std::filesystem::path>& files)
{
    std::string command = fmt::format("node {}", PENUMBRA_GLTF_VALIDATE_SCRIPT);
    for (const std::filesystem::path& file : files)
        command += " '" + file.string() + "'";
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
    std::map<std::string, Verdict> verdicts;
    if (!pipe)
        return verdicts;
    std::string output;
    std::array<char, 4096> chunk{};
    while (const std::size_t read = std::fread(chunk.data(), 1, chunk.size(), pipe.get()))
        output.append(chunk.data(), read);
    std::size_t start = 0;
    while (start < output.size()) {
        const std::size_t end = std::min(output.find('\n', start), output.size());
        const nlohmann::json line = nlohmann::json::parse(output.substr(start, end - start), nullptr, false);
        start = end + 1;
        if (!line.is_object())
            continue;
        Verdict& verdict = verdicts[line["file"].get<std::string>()];
        for (const nlohmann::json& error : line["errors"]) {
            verdict.codes.push_back(error["code"]);
            verdict.errors +=
                fmt::format("{} at {}; ", error["code"].get<std::string>(), error["pointer"].get<std::string>());
        }
    }
    return verdicts;
}

// What the validator calls an error but the loader accepts with a note (the README lists them): a note naming the
// deviation is the loader's answer.
const std::map<std::string, std::string> kTolerated{
    {"ACCESSOR_MIN_MISMATCH", "min/max"},
    {"ACCESSOR_MAX_MISMATCH", "min/max"},
    {"ACCESSOR_ELEMENT_OUT_OF_MIN_BOUND", "min/max"},
    {"ACCESSOR_ELEMENT_OUT_OF_MAX_BOUND", "min/max"},
    {"ACCESSOR_NON_UNIT", "not unit"},
    {"ACCESSOR_VECTOR3_NON_UNIT", "not unit"},
    {"MESH_PRIMITIVE_POSITION_ACCESSOR_WITHOUT_BOUNDS", "min/max"},
};

std::string joined(const std::vector<std::string>& lines)
{
    std::string out;
    for (const std::string& line : lines)
        out += line + " | ";
    return out;
}

// Two instances of the cube, the second one's ROTATION a normalized SHORT quaternion. The validator (2.0.0-dev.3.10)
// does not know EXT_mesh_gpu_instancing (an UNSUPPORTED_EXTENSION info, not an error): it judges the file's accessors,
// not the extension's rules, which GltfInstancingTest.cpp checks.
GltfBuilder instancedCubes()
{
    GltfBuilder b;
    testing::addCubeMesh(b, "Cube", -1);
    b.addRoot(testing::addInstancedNode(b, {{"name", "cubes"}, {"mesh", 0}},
                                        {.translations = {{0, 0, 0}, {3, 0, 0}},
                                         .rotations = {{0, 0, 0, 1}, {0, 0.7071068f, 0, 0.7071068f}},
                                         .scales = {{1, 1, 1}, {0.5f, 2, 0.5f}},
                                         .rotationComponent = Component::Short}));
    return b;
}

TEST_F(GltfLoaderTest, TheRepositorysScenesAreValid)
{
    const std::vector<std::filesystem::path> files{write(cubeScene(), "cube.gltf"),
                                                   write(testing::exampleScene(), "example.gltf"),
                                                   write(testing::materialsScene(), "materials.glb"),
                                                   write(instancedCubes(), "instanced.gltf"),
                                                   write(testing::twoBoneBendScene(), "bend.gltf"),
                                                   write(testing::morphScene(), "morph.gltf"),
                                                   write(testing::keyframeScene(), "keyframes.gltf")};
    const std::map<std::string, Verdict> verdicts = validate(files);
    ASSERT_EQ(verdicts.size(), files.size()) << "is the glTF Validator installed (scripts/install-deps.sh)?";
    for (const std::filesystem::path& file : files) {
        EXPECT_EQ(verdicts.at(file.string()).errors, "") << file;
        EXPECT_NO_THROW(gltf::loadGltf(file)) << file;
    }
}

// Writes `count` seeded mutants of `sources`, has the validator and the loader judge each, and expects the same
// verdict.
void judgeMutants(const std::filesystem::path& folder, const std::vector<nlohmann::json>& sources, std::size_t kMutants,
                  std::uint32_t kSeed)
{
    const std::vector<testing::GltfMutant> mutants = testing::mutateGltf(sources, kMutants, kSeed);
    std::vector<std::filesystem::path> files;
    for (std::size_t i = 0; i < mutants.size(); ++i) {
        files.push_back(folder / fmt::format("mutant-{:03}.gltf", i));
        std::ofstream(files.back()) << mutants[i].document.dump(1);
    }
    const std::map<std::string, Verdict> verdicts = validate(files);
    ASSERT_EQ(verdicts.size(), files.size()) << "is the glTF Validator installed (scripts/install-deps.sh)?";

    std::size_t rejected = 0, loaded = 0;
    for (std::size_t i = 0; i < mutants.size(); ++i) {
        const Verdict& verdict = verdicts.at(files[i].string());
        std::string refusal;
        std::vector<std::string> notes;
        try {
            notes = gltf::loadGltf(files[i]).notes;
            ++loaded;
        } catch (const gltf::GltfError& error) {
            refusal = error.what();
        }
        const std::string context =
            fmt::format("{} ({}): validator: [{}] loader: {}", files[i].filename().string(), mutants[i].change,
                        verdict.errors, refusal.empty() ? "loaded, notes: " + joined(notes) : refusal);
        if (verdict.codes.empty()) {
            EXPECT_TRUE(refusal.empty() || refusal.find("not supported") != std::string::npos) << context;
            continue;
        }
        ++rejected;
        if (!refusal.empty())
            continue;
        for (const std::string& code : verdict.codes) {
            const auto tolerated = kTolerated.find(code);
            EXPECT_TRUE(tolerated != kTolerated.end() && joined(notes).find(tolerated->second) != std::string::npos)
                << code << " is not refused or noted: " << context;
        }
    }
    // Both verdicts occur, so neither half of the comparison is empty.
    EXPECT_GT(rejected, kMutants / 4);
    EXPECT_GT(loaded, kMutants / 10);
}

TEST_F(GltfLoaderTest, MutantsAreJudgedAsTheValidatorJudgesThem)
{
    judgeMutants(folder_,
                 {cubeScene().embedded(), testing::exampleScene().embedded(), testing::materialsScene().embedded()},
                 150, 15);
}

// Skins, morph targets and animations: the animation tests' files mutated.
TEST_F(GltfLoaderTest, AnimatedMutantsAreJudgedAsTheValidatorJudgesThem)
{
    judgeMutants(folder_,
                 {testing::twoBoneBendScene().embedded(), testing::morphScene().embedded(),
                  testing::keyframeScene().embedded()},
                 120, 43);
}

} // namespace
} // namespace penumbra::scene
