#include <catch2/catch.hpp>

#include "kinergy/common/error.hpp"
#include "kinergy/units/units.hpp"

using namespace kinergy::units;
using GiNaC::ex;
using GiNaC::numeric;

TEST_CASE("decimals are read exactly", "[units]") {
  std::size_t i = 0;
  numeric v;
  REQUIRE(parse_decimal("9.81", i, v));
  CHECK(v == numeric(981, 100));
  i = 0;
  REQUIRE(parse_decimal("1e-6", i, v));
  CHECK(v == numeric(1, 1000000));
  int sf = 0;
  i = 0;
  REQUIRE(parse_decimal("3.50", i, v, &sf));
  CHECK(sf == 3);
  i = 0;
  REQUIRE(parse_decimal("0.00120", i, v, &sf));
  CHECK(sf == 3);
}

TEST_CASE("units convert exactly to SI", "[units]") {
  CHECK((parse_quantity("30 deg").si - GiNaC::Pi / 6).is_zero());
  CHECK(parse_quantity("1 ft").si == numeric(3048, 10000));
  CHECK(parse_quantity("2 lb").unit.dim == parse_unit("N").dim);
  CHECK((parse_quantity("60 rpm").si - 2 * GiNaC::Pi).is_zero());
  CHECK(parse_unit("N*m").dim == parse_unit("J").dim);
  CHECK(parse_unit("N\u00b7m").dim == parse_unit("lb*ft").dim);
  CHECK(parse_unit("kg*m^2").dim == parse_unit("slug*ft^2").dim);
  CHECK(parse_unit("m/s^2").dim == Dimension::length() / Dimension::time().pow(2));
  // 1 slug = 1 lbf s²/ft = 14.5939029372064 kg
  ex slug = parse_quantity("1 slug").si;
  CHECK(std::abs(GiNaC::ex_to<numeric>(slug.evalf()).to_double() - 14.5939029372064) < 1e-12);
  // 1 hp = 550 ft lbf / s = 745.69987158227022 W (exact)
  CHECK(parse_quantity("1 hp").si == numeric(74569987158227022LL, 100000000000000LL));
  auto q = parse_quantity("unknown N/m");
  CHECK(q.unknown);
  CHECK(!q.has_number);
  auto mu = parse_quantity("0.4");
  CHECK(mu.unit.dim.dimensionless());
}

TEST_CASE("bad units are named with their column", "[units][errors]") {
  try {
    parse_quantity("5 kgs");
    FAIL("no error");
  } catch (const kinergy::InputError& e) {
    CHECK(std::string(e.what()).find("unknown unit 'kgs'") != std::string::npos);
    CHECK(e.column() == 3);
  }
  CHECK_THROWS_AS(parse_unit("m/"), kinergy::InputError);
  CHECK_THROWS_AS(parse_quantity("unknown"), kinergy::InputError);
  CHECK_THROWS_AS(parse_unit("m^x"), kinergy::InputError);
}

TEST_CASE("SI names of dimensions", "[units]") {
  CHECK(si_name(parse_unit("rad/s").dim) == "rad/s");
  CHECK(si_name(parse_unit("N*m").dim) == "J");
  CHECK(si_name(parse_unit("ft/s").dim) == "m/s");
  CHECK(si_name(parse_unit("hp").dim) == "W");
}
