// Using penner as an oracle from C++17 (no dependencies).
//
// Writes claims about a unit tetrahedron (cone angles, its hyperbolic uniformization) and
// about a unit square (flipping to intrinsic Delaunay), runs `penner certify` on each, and reads the verdict from the JSON
// answer and the exit code. Usage:
//
//     g++ -std=c++17 -O2 -o cpp_client examples/oracle/cpp_client.cpp
//     ./cpp_client path/to/penner
//
// Exit status 0 when every answer is the expected one.

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace {

// The value of a top-level string or literal field `"key": value` in a flat JSON answer.
// Enough for the fields this client reads; a real client would use a JSON library.
std::string field(const std::string& json, const std::string& key) {
    const std::string needle = "\"" + key + "\"";
    auto at = json.find(needle);
    if (at == std::string::npos) return "";
    at = json.find(':', at + needle.size());
    if (at == std::string::npos) return "";
    ++at;
    while (at < json.size() && (json[at] == ' ' || json[at] == '\n')) ++at;
    if (at < json.size() && json[at] == '"') {
        auto end = json.find('"', at + 1);
        return json.substr(at + 1, end - at - 1);
    }
    auto end = json.find_first_of(",\n}", at);
    return json.substr(at, end - at);
}

struct Result {
    int exit_code;
    std::string answer;
};

Result certify(const std::string& penner, const std::string& claim) {
    char path[] = "/tmp/penner-claim-XXXXXX";
    int fd = mkstemp(path);
    if (fd < 0) {
        std::perror("mkstemp");
        std::exit(2);
    }
    close(fd);
    std::ofstream(path) << claim;
    const std::string cmd = "'" + penner + "' certify '" + path + "' 2>/dev/null";
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) {
        std::perror("popen");
        std::exit(2);
    }
    std::string out;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) out.append(buf, n);
    int status = pclose(pipe);
    std::remove(path);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

const char* kSurface =
    R"({"vertices": 4, "faces": [[0,1,2],[0,2,3],[0,3,1],[1,3,2]],)"
    R"( "lengths": ["1","1","1","1","1","1"]})";

// A unit square split by the diagonal 0-2 (squared lengths, edges in order of first
// appearance: 01, 12, 20, 23, 30). Its four corners are cocircular, so the diagonal is a
// tie (D = 0): both diagonals give Delaunay triangulations.
const char* kSquare =
    R"({"vertices": 4, "faces": [[0,1,2],[0,2,3]], "squared_lengths": ["1","1","2","1","1"]})";

// The same square split by the other diagonal 1-3 (edges 01, 13, 30, 12, 23), whose
// squared length is `diagonal`.
std::string other_diagonal(const std::string& diagonal) {
    return R"({"vertices": 4, "faces": [[0,1,3],[1,2,3]], "squared_lengths": ["1",")" + diagonal +
           R"(","1","1","1"]})";
}

// A `delaunay_flip` claim: flipping kSquare to intrinsic Delaunay with Euclidean flips
// gives `result` (up to renumbering of edges and faces; vertices keep their ids).
std::string flip_claim(const std::string& result) {
    return std::string(R"({"penner_claim": 1, "kind": "delaunay_flip", "flips": "euclidean", "surface": )") +
           kSquare + R"(, "result": )" + result + "}";
}

// A `hyperbolic_uniformization` claim about kSurface read as a hyperbolic metric (all
// sides 1): cone angles `targets` (multiples of pi) reached by the sinh scaling with u at
// every vertex. For targets pi/2 the exact u* = ln((1 + sqrt 3)/sinh^2(1/2))/2 (each
// equilateral corner pi/6); `u` below is it to 60 digits, as another solver would give it.
std::string hyperbolic_claim(const std::string& target, const std::string& u) {
    const std::string t = "\"" + target + "\"";
    const std::string v = "\"" + u + "\"";
    return std::string(R"({"penner_claim": 1, "kind": "hyperbolic_uniformization", "max_bits": 256, "surface": )") +
           kSurface + R"(, "targets": [)" + t + "," + t + "," + t + "," + t + R"(], "u": [)" + v + "," + v + "," + v +
           "," + v + R"(], "radius": "1e-40", "residual_bound": "1e-40"})";
}

const char* kHyperbolicU = "1.15434859531821770494944538371704252297809856750939233242797";

}  // namespace

int main(int argc, char** argv) {
    const std::string penner = argc > 1 ? argv[1] : "target/release/penner";
    const std::string pi = "\"3.141592653589793238462643383279502884197\"";
    struct Case {
        const char* what;
        std::string claim;
        const char* verdict;
        int exit_code;
    } cases[] = {
        {"true cone angles",
         std::string(R"({"penner_claim": 1, "kind": "cone_angles", "surface": )") + kSurface +
             R"(, "angles": [)" + pi + "," + pi + "," + pi + "," + pi + R"(], "epsilon": "1e-35"})",
         "holds", 0},
        {"cone angles 3.0 (too small)",
         std::string(R"({"penner_claim": 1, "kind": "cone_angles", "surface": )") + kSurface +
             R"(, "angles": [3.0, 3.0, 3.0, 3.0], "epsilon": "0.1"})",
         "refuted", 1},
        {"square, other diagonal (a tie flip)", flip_claim(other_diagonal("2")), "holds", 0},
        {"square, other diagonal of squared length 3", flip_claim(other_diagonal("3")), "refuted", 1},
        {"malformed claim", R"({"penner_claim": 1, "kind": "cone_angles"})", "bad_input", 3},
        {"Lobachevsky: L(1/2) = Cl2(1)/2",
         R"({"penner_claim": 1, "kind": "lobachevsky", "x": "0.5",)"
         R"( "y": "0.506979566180384252147287169443", "epsilon": "1e-25"})",
         "holds", 0},
        {"circle packing: radii 1, 2, 3 on the 3-4-5 triangle",
         R"({"penner_claim": 1, "kind": "circle_packing", "surface": {"vertices": 3, "faces": [[0,1,2]]},)"
         R"( "centres": [["0","0"],["3","0"],["0","4"]], "radii": ["1","2","3"], "epsilon": "1e-30"})",
         "holds", 0},
        {"circle packing with radius 3 -> 3.001",
         R"({"penner_claim": 1, "kind": "circle_packing", "surface": {"vertices": 3, "faces": [[0,1,2]]},)"
         R"( "centres": [["0","0"],["3","0"],["0","4"]], "radii": ["1","2","3.001"], "epsilon": "1e-9"})",
         "refuted", 1},
        {"circle pattern: touching unit circles on the tetrahedron",
         std::string(R"({"penner_claim": 1, "kind": "circle_pattern", "surface": )") + kSurface +
             R"(, "radii": ["1","1","1","1"], "phi_over_pi": ["0","0","0","0","0","0"], "angles": [)" + pi + "," +
             pi + "," + pi + "," + pi + R"(], "epsilon": "1e-35"})",
         "holds", 0},
        {"sphere uniformization of the tetrahedron, pole 0 (the disk is one triangle)",
         std::string(R"({"penner_claim": 1, "kind": "sphere_uniformization", "surface": )") + kSurface +
             R"(, "euclidean_flips": [], "pole": 0, "flips": [], "u": [null,null,null,null],)"
             R"( "radius": "1e-9", "final_faces": [[0,1,2],[0,2,3],[0,3,1],[1,3,2]], "residual_bound": "0"})",
         "holds", 0},
        {"hyperbolic tetrahedron: cone angles pi/2 at u to 60 digits", hyperbolic_claim("1/2", kHyperbolicU),
         "holds", 0},
        {"hyperbolic tetrahedron with an (empty) flip sequence: hyperbolic Delaunay, certified",
         hyperbolic_claim("1/2", kHyperbolicU).substr(0, hyperbolic_claim("1/2", kHyperbolicU).size() - 1) +
             R"(, "flips": []})",
         "holds", 0},
        {"hyperbolic tetrahedron: u rounded to 1.154349", hyperbolic_claim("1/2", "1.154349"), "refuted", 1},
        {"hyperbolic target 2 pi on a sphere (Gauss-Bonnet leaves no area)", hyperbolic_claim("2", "0"),
         "refuted", 1},
    };
    int failures = 0;
    for (const auto& c : cases) {
        const Result r = certify(penner, c.claim);
        const std::string verdict = field(r.answer, "verdict");
        const bool ok = verdict == c.verdict && r.exit_code == c.exit_code;
        std::cout << c.what << ": verdict=" << verdict << " certified=" << field(r.answer, "certified")
                  << " bits=" << field(r.answer, "precision_bits") << " exit=" << r.exit_code << " -> "
                  << (ok ? "ok" : "UNEXPECTED") << "\n";
        failures += !ok;
    }
    if (failures) {
        std::cerr << failures << " unexpected answer(s)\n";
        return 1;
    }
    return 0;
}
