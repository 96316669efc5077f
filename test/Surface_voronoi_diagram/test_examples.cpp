// The examples and the manual stay in step: every example program that CMake builds exists,
// is listed for doxygen and is shown in the manual; every example the manual shows is built. Running them needs -DSVD_BUILD_EXAMPLES=ON, which the
// test build does not have: scripts/check_examples.sh does that.
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

// this file's own names: the suite compiles its files together (see CMakeLists.txt)
namespace svd_test_examples {

namespace {

std::string read_text(const std::string& path)
{
  std::ifstream in(path);
  REQUIRE(in);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::set<std::string> matches(const std::string& text, const std::regex& pattern)
{
  std::set<std::string> out;
  for(std::sregex_iterator it(text.begin(), text.end(), pattern), end; it != end; ++it) out.insert((*it)[1]);
  return out;
}

} // namespace

TEST_CASE("examples: every built example is listed and shown in the manual", "[examples]")
{
  const std::string root = SVD_SOURCE_DIR;
  const std::string cmake = read_text(root + "/examples/Surface_voronoi_diagram/CMakeLists.txt");
  std::smatch list;
  REQUIRE(std::regex_search(cmake, list, std::regex("set\\(SVD_EXAMPLES([^)]*)\\)")));
  std::set<std::string> built = matches(list[1].str(), std::regex("([A-Za-z_0-9]+)"));
  // and the ones built on a condition (draw_diagram needs Qt5)
  for(const std::string& name : matches(cmake, std::regex("add_executable\\((\\w+) ")))
    if(name.find('$') == std::string::npos) built.insert(name);
  const std::set<std::string> listed =
      matches(read_text(root + "/doc/Surface_voronoi_diagram/examples.txt"), std::regex("\\\\example Surface_voronoi_diagram/(\\w+)\\.cpp"));
  const std::set<std::string> shown = matches(read_text(root + "/doc/Surface_voronoi_diagram/Surface_voronoi_diagram.txt"),
                                              std::regex("\\\\cgalExample\\{Surface_voronoi_diagram/(\\w+)\\.cpp\\}"));
  CHECK(built.size() >= 8);
  for(const std::string& name : built)
  {
    INFO(name);
    CHECK(std::ifstream(root + "/examples/Surface_voronoi_diagram/" + name + ".cpp").good());
    CHECK(listed.count(name) == 1);
    CHECK(shown.count(name) == 1);
  }
  for(const std::string& name : shown)
  {
    INFO(name);
    CHECK(built.count(name) == 1);
  }
}

} // namespace svd_test_examples
