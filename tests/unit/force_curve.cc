// The set force over the punch travel (parameters/force_curve.cc): one
// number is constant; a table is linear between its points and held at its
// end values beyond; the text reads back; a table whose travels do not
// increase, an item that is not travel:force, or a travel before 0 is
// refused naming the entry.
#include <formsolve/parameters/force_curve.h>

#include "check.h"

#include <string>

using formsolve::parameters::ForceCurve;

namespace
{
  bool refused(const std::string &text, const std::string &words)
  {
    try
      {
        ForceCurve::read(text, "Tools/Blank holder/Force");
      }
    catch (const std::exception &e)
      {
        const std::string what = e.what();
        return what.find("Tools/Blank holder/Force") != std::string::npos &&
               what.find(words) != std::string::npos;
      }
    return false;
  }
} // namespace

int main()
{
  const ForceCurve c = ForceCurve::read("2671", "Force");
  test::close("a number: constant", c.at(0) + c.at(40), 2 * 2671, 0);
  test::close("... does not vary", c.varies(), 0, 0);

  const ForceCurve t = ForceCurve::read(" 2:1000, 6:3000 ,10:2000", "Force");
  test::close("before the first travel: the first force", t.at(0), 1000, 0);
  test::close("linear in between", t.at(3), 1500, 1e-12);
  test::close("... on the falling part", t.at(9), 2250, 1e-12);
  test::close("after the last travel: the last force", t.at(50), 2000, 0);
  test::close("smallest", t.smallest(), 1000, 0);
  test::close("largest", t.largest(), 3000, 0);
  test::close("the text reads back",
              ForceCurve::read(t.text(), "Force").at(7),
              t.at(7),
              0);

  test::close("decreasing travels refused",
              refused("0:1000, 10:2000, 5:3000", "must increase"),
              1,
              0);
  test::close("an item without a colon refused",
              refused("0:1000, 10 2000", "is not 'travel:force'"),
              1,
              0);
  test::close("words refused", refused("strong", "is not accepted"), 1, 0);
  test::close("a travel before 0 refused",
              refused("-1:1000, 10:2000", "start at 0 mm"),
              1,
              0);
  return test::result();
}
