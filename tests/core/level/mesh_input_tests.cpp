#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <limits>

#include "io/obj_reader.h"
#include "level/mesh_validation.h"
#include "util/error.h"

using nl::ErrorCode;
using nl::TriangleMesh;
using nl::Vec3;

namespace {

TriangleMesh quad() {
    TriangleMesh m;
    m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(0, 0, 1)};
    m.triangles = {{0, 2, 1}, {0, 3, 2}};
    return m;
}

ErrorCode code_of(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const nl::Error& e) {
        return e.code();
    }
    FAIL("expected an nl::Error");
    return ErrorCode::Internal;
}

std::string message_of(const std::function<void()>& fn) {
    try {
        fn();
    } catch (const nl::Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("validation keeps good triangles and maps kept ones back to their input index") {
    TriangleMesh m = quad();
    m.vertices.push_back(Vec3(2, 0, 0));
    m.triangles.insert(m.triangles.begin() + 1, {0, 1, 4});  // collinear: zero area
    m.triangles.push_back({1, 1, 2});                        // repeated index
    const nl::ValidatedTriangles v = nl::validate_mesh(m);
    CHECK(v.degenerate_count == 2);
    REQUIRE(v.kept.size() == 2);
    REQUIRE(v.input_index.size() == 2);
    CHECK(v.input_index[0] == 0);
    CHECK(v.input_index[1] == 2);
}

TEST_CASE("validation with no degenerate triangle leaves the index map empty (identity)") {
    const nl::ValidatedTriangles v = nl::validate_mesh(quad());
    CHECK(v.degenerate_count == 0);
    CHECK(v.input_index.empty());
    CHECK(v.kept.size() == 2);
}

TEST_CASE("validation names the bad value") {
    TriangleMesh m = quad();
    m.vertices[2].y() = std::numeric_limits<float>::quiet_NaN();
    CHECK(code_of([&] { nl::validate_mesh(m); }) == ErrorCode::InvalidArgument);
    CHECK(message_of([&] { nl::validate_mesh(m); }).find("vertices[2].y") != std::string::npos);

    m = quad();
    m.vertices[1].x() = std::numeric_limits<float>::infinity();
    CHECK(message_of([&] { nl::validate_mesh(m); }).find("vertices[1].x") != std::string::npos);

    m = quad();
    m.triangles[1][2] = 4;
    CHECK(message_of([&] { nl::validate_mesh(m); }).find("indices[5] = 4 is out of range") != std::string::npos);

    m = quad();
    m.triangles = {{0, 1, 1}};
    CHECK(message_of([&] { nl::validate_mesh(m); }).find("degenerate") != std::string::npos);

    CHECK(code_of([] { nl::validate_mesh(TriangleMesh{}); }) == ErrorCode::InvalidArgument);
}

TEST_CASE("transforms must be finite, affine and invertible") {
    Eigen::Matrix4f m = Eigen::Matrix4f::Identity();
    m(0, 3) = 5.0f;
    CHECK(nl::validate_transform(m, "t").translation().x() == 5.0f);
    Eigen::Matrix4f projective = m;
    projective(3, 2) = 1.0f;
    CHECK(message_of([&] { nl::validate_transform(projective, "t"); }).find("not affine") != std::string::npos);
    Eigen::Matrix4f flat = Eigen::Matrix4f::Identity();
    flat(1, 1) = 0.0f;
    CHECK(message_of([&] { nl::validate_transform(flat, "t"); }).find("singular") != std::string::npos);
    Eigen::Matrix4f nan = Eigen::Matrix4f::Identity();
    nan(2, 0) = std::numeric_limits<float>::quiet_NaN();
    CHECK(code_of([&] { nl::validate_transform(nan, "t"); }) == ErrorCode::InvalidArgument);
}

TEST_CASE("OBJ: polygons are fan-triangulated, other statements ignored") {
    const char* text =
        "# comment\n"
        "mtllib missing.mtl\n"
        "o thing\n"
        "v 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nv 0.5 0 1.5\n"
        "vn 0 1 0\n"
        "usemtl stone\n"
        "f 1//1 2//1 3//1 4//1 5//1\n"
        "f 1 2 3\n";
    const TriangleMesh m = nl::read_obj_text(text);
    CHECK(m.vertices.size() == 5);
    REQUIRE(m.triangles.size() == 4);
    CHECK(m.triangles[0] == nl::Triangle{0, 1, 2});
    CHECK(m.triangles[1] == nl::Triangle{0, 2, 3});
    CHECK(m.triangles[2] == nl::Triangle{0, 3, 4});
    CHECK(m.triangles[3] == nl::Triangle{0, 1, 2});
}

TEST_CASE("OBJ: negative (relative) indices resolve to earlier vertices") {
    const TriangleMesh m = nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nf -3 -2 -1\n");
    REQUIRE(m.triangles.size() == 1);
    CHECK(m.triangles[0] == nl::Triangle{0, 1, 2});
}

TEST_CASE("OBJ: malformed files are parse errors with the reason") {
    CHECK(code_of([] { nl::read_obj_text(""); }) == ErrorCode::Parse);
    // A binary file says so, not "no faces".
    CHECK(message_of([] {
              nl::read_obj_text(std::string_view("\x7f"
                                                 "ELF\x02\x01\x01\0\0v 1 2 3\n",
                                                 15),
                                "ls.obj");
          }) == "ls.obj: not a text file (a NUL byte at offset 7): an OBJ file is text");
    CHECK(code_of([] { nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\n"); }) == ErrorCode::Parse);
    CHECK(code_of([] { nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 9\n"); }) == ErrorCode::Parse);
    CHECK(code_of([] { nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 0\n"); }) == ErrorCode::Parse);
    CHECK(code_of([] { nl::read_obj_text("v 0 0 0\nf -5 -6 -7\n"); }) == ErrorCode::Parse);
    CHECK(code_of([] { nl::read_obj_file("/nonexistent/level.obj"); }) == ErrorCode::NotFound);
    CHECK(code_of([] { nl::read_obj_file("/"); }) == ErrorCode::Io);
}

TEST_CASE("OBJ: numbers tinyobjloader would read as 0 are refused, with the line") {
    const char* tail = "v 1 0 0\nv 0 0 1\nf 1 2 3\n";
    for (const char* bad : {"v abc 0 0\n", "v nan 0 0\n", "v inf 0 0\n", "v 0 0\n", "v 1e39 0 0\n"}) {
        CAPTURE(bad);
        CHECK(code_of([&] { nl::read_obj_text(std::string(bad) + tail); }) == ErrorCode::Parse);
    }
    CHECK(message_of([&] { nl::read_obj_text(std::string("# level\nv 0 0 0\nv x 0 0\n") + tail); }).find(":3:") !=
          std::string::npos);
    CHECK(code_of([] { nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 4294967297\n"); }) == ErrorCode::Parse);
    CHECK(code_of([] { nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 three\n"); }) == ErrorCode::Parse);
    CHECK(code_of([] { nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2\n"); }) == ErrorCode::Parse);
    // Texture and normal parts after the position index are not our business.
    CHECK(nl::read_obj_text("v 0 0 0\nv 1 0 0\nv 0 0 1\nvt 0 0\nf 1/1 2/1 3/1\n").triangles.size() == 1);
}

TEST_CASE("coordinates beyond the limit are refused, and huge scales are not mistaken for singular") {
    TriangleMesh m = quad();
    m.vertices[3].z() = 2e9f;
    // The core names the field; a caller that knows the input by another name puts it in front.
    CHECK(message_of([&] { nl::validate_mesh(m); }).rfind("vertices[3].z", 0) == 0);
    CHECK(message_of([&] {
              nl::naming_fields("def->", [&] { nl::validate_mesh(m); });
          }).rfind("def->vertices[3].z", 0) == 0);
    Eigen::Matrix4f big = Eigen::Matrix4f::Identity() * 1e13f;
    big(3, 3) = 1.0f;
    CHECK_NOTHROW(nl::validate_transform(big, "t"));
}

TEST_CASE("the normal matrix keeps the winding's orientation under mirroring") {
    nl::Transform mirror = nl::Transform::Identity();
    mirror.scale(Vec3(-1, 1, 1));
    // Winding +Y in object space, mirrored in x: the world-space triangle winds the other way.
    const Vec3 a(0, 0, 0), b(0, 0, 1), c(1, 0, 0);
    const Vec3 world_normal = ((mirror * b) - (mirror * a)).cross((mirror * c) - (mirror * a)).normalized();
    const Vec3 object_normal = (b - a).cross(c - a).normalized();
    CHECK(((nl::normal_matrix(mirror) * object_normal).normalized() - world_normal).norm() < 1e-6f);
}

TEST_CASE("OBJ: every line ending tinyobjloader knows ends a line for the check too") {
    // A lone \r ended tinyobjloader's lines but not the check's: behind a comment the whole file was
    // one unchecked line, and `nan` loaded as 0 (a vertex moved to the origin).
    CHECK(code_of([] { nl::read_obj_text("# level\rv 0 0 0\rv 1 0 0\rv nan 0 1\rf 1 2 3\r"); }) == ErrorCode::Parse);
    CHECK(message_of([] { nl::read_obj_text("# level\rv 0 0 0\rv 1 0 0\rv nan 0 1\rf 1 2 3\r"); }).find(":4:") !=
          std::string::npos);
    for (const char* eol : {"\n", "\r\n", "\r"}) {
        CAPTURE(eol);
        std::string text;
        for (const char* line : {"# level", "v 0 0 0", "v 1 0 0", "v 0 2 1", "f 1 2 3"})
            text += std::string(line) + eol;
        const TriangleMesh m = nl::read_obj_text(text);
        REQUIRE(m.vertices.size() == 3);
        CHECK(m.vertices[2] == Vec3(0, 2, 1));
        CHECK(m.triangles.size() == 1);
    }
    // Mixed in one file, and a last line with no ending.
    CHECK(nl::read_obj_text("v 0 0 0\r\nv 1 0 0\rv 0 0 1\nf 1 2 3").triangles.size() == 1);
}

TEST_CASE("OBJ: records NavLink does not read never reach tinyobjloader") {
    // tinyobjloader parses vertex weights with no checks: a negative joint failed the whole file, and
    // 1e30 was converted to an int (undefined behaviour). Lines, points and tags are its own too.
    const char* tail = "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n";
    for (const char* line : {"vw 0 1e30 0.5\n", "vw 0 -1 0.5\n", "l 1 99999999999\n", "p -7\n", "t crease 2/1/1 1e99\n",
                             "vp nan\n", "curv 0 1 2\n", "usemtl x\n", "s off\n", "mtllib ../../etc/passwd\n"}) {
        CAPTURE(line);
        CHECK(nl::read_obj_text(std::string(line) + tail).triangles.size() == 1);
    }
}

TEST_CASE("OBJ: texture and normal indices of a face are checked, though not read") {
    const char* head = "v 0 0 0\nv 1 0 0\nv 0 0 1\nvt 0 0\nvn 0 1 0\n";
    for (const char* face : {"f 1/1 2/1 3/1\n", "f 1//1 2//1 3//1\n", "f 1/1/1 2/1/1 3/-1/-1\n"}) {
        CAPTURE(face);
        CHECK(nl::read_obj_text(std::string(head) + face).triangles.size() == 1);
    }
    for (const char* face : {"f 1/2 2/1 3/1\n", "f 1//2 2//1 3//1\n", "f 1/ 2/ 3/\n", "f 1/1/1/1 2 3\n", "f 1/x 2 3\n",
                             "f 1/-2 2 3\n", "f 1/1/ 2 3\n"}) {
        CAPTURE(face);
        CHECK(code_of([&] { nl::read_obj_text(std::string(head) + face); }) == ErrorCode::Parse);
    }
}

TEST_CASE("OBJ: a message quotes a bad token short") {
    const std::string huge(100000, '9');
    const std::string message = message_of([&] { nl::read_obj_text("v " + huge + "x 0 0\n"); });
    CHECK(message.find(":1:") != std::string::npos);
    CHECK(message.size() < 200);
}

TEST_CASE("OBJ: a file that fails while it is read is an I/O error, not a parse error of what came before") {
    // Reading /proc/self/mem from offset 0 fails (EIO): the address is not mapped.
    if (!std::ifstream("/proc/self/mem")) return;  // no /proc here
    CHECK(code_of([] { nl::read_obj_file("/proc/self/mem"); }) == ErrorCode::Io);
    CHECK(message_of([] { nl::read_obj_file("/proc/self/mem"); }).find("cannot read '/proc/self/mem'") !=
          std::string::npos);
}
