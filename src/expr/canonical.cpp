#include "kinergy/expr/canonical.hpp"

#include <unordered_map>

#include <algorithm>
#include <sstream>
#include <vector>

namespace kinergy::expr {

using namespace GiNaC;

namespace {

std::string number_text(const numeric& n) {
  std::ostringstream os;
  os << n;
  return os.str();
}

std::string joined(std::vector<std::string> keys, const char* sep) {
  std::sort(keys.begin(), keys.end());
  std::string s;
  for (std::size_t i = 0; i < keys.size(); ++i) s += (i ? sep : "") + keys[i];
  return s;
}

/// A sum's terms, each by its key, and whether the sum is to be read negated.
struct Oriented {
  std::vector<Key> terms;
  bool flip = false;
};

Oriented orient(const ex& sum) {
  Oriented o;
  int pos = 0, neg = 0;
  std::size_t first = 0;
  for (std::size_t i = 0; i < sum.nops(); ++i) {
    o.terms.push_back(key(sum.op(i)));
    (o.terms.back().negative ? neg : pos)++;
    if (o.terms.back().text < o.terms[first].text) first = i;
  }
  // more negative terms than positive, or as many and the first by key negative: read −(…)
  o.flip = neg > pos || (neg == pos && !o.terms.empty() && o.terms[first].negative);
  return o;
}

}  // namespace

bool reversed(const ex& sum) { return is_a<add>(sum) && orient(sum).flip; }

namespace {

Key compute_key(const ex& e);

struct Hash {
  std::size_t operator()(const ex& e) const { return e.gethash(); }
};
struct Equal {
  bool operator()(const ex& a, const ex& b) const { return a.is_equal(b); }
};

}  // namespace

// A key is a function of the expression alone: kept, so that sorting the terms of a large sum
// by key (and the keys of its parts inside theirs) costs each subexpression's text once, not once
// per comparison and per level. Bounded: cleared when it holds many.
Key key(const ex& e) {
  if (is_a<numeric>(e) || is_a<symbol>(e)) return compute_key(e);
  thread_local std::unordered_map<ex, Key, Hash, Equal> known;
  auto it = known.find(e);
  if (it != known.end()) return it->second;
  Key k = compute_key(e);
  if (known.size() > 50000) known.clear();
  known.emplace(e, k);
  return k;
}

namespace {

Key compute_key(const ex& e) {
  if (is_a<numeric>(e)) {
    const numeric& n = ex_to<numeric>(e);
    if (n.is_real() && n.is_negative()) return {true, "#" + number_text(-n)};
    return {false, "#" + number_text(n)};
  }
  if (is_a<symbol>(e)) return {false, ex_to<symbol>(e).get_name()};
  if (is_a<constant>(e)) {
    std::ostringstream os;
    os << e;
    return {false, os.str()};
  }
  if (is_a<add>(e)) {
    // the sum as written is the oriented one, or its negative (flip)
    Oriented o = orient(e);
    std::vector<std::string> ts;
    for (auto& t : o.terms) ts.push_back(std::string(t.negative != o.flip ? "-" : "+") + t.text);
    return {o.flip, "(" + joined(ts, " ") + ")"};
  }
  if (is_a<mul>(e)) {
    bool negative = false;
    std::vector<std::string> fs;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      Key k = key(e.op(i));
      negative = negative != k.negative;
      if (k.text != "#1") fs.push_back(k.text);
    }
    if (fs.size() == 1) return {negative, fs[0]};  // −x is x with a sign
    return {negative, "{" + joined(fs, "*") + "}"};
  }
  if (is_a<power>(e)) {
    const ex& b = e.op(0);
    const ex& k = e.op(1);
    bool integer = is_a<numeric>(k) && ex_to<numeric>(k).is_integer();
    if (integer && is_a<add>(b)) {
      // (−s)^n = (−1)^n s^n: the sign of an oriented sum comes out of an integer power
      Key kb = key(b);
      return {kb.negative && ex_to<numeric>(k).is_odd(), kb.text + "^" + key(k).full()};
    }
    return {false, "[" + key(b).full() + "]^" + key(k).full()};
  }
  std::vector<std::string> args;
  for (std::size_t i = 0; i < e.nops(); ++i) args.push_back(key(e.op(i)).full());
  std::string name = is_a<function>(e) ? ex_to<function>(e).get_name() : std::string(ex_to<basic>(e).class_name());
  std::string s = name + "(";
  for (std::size_t i = 0; i < args.size(); ++i) s += (i ? "," : "") + args[i];
  return {false, s + ")"};
}

}  // namespace

}  // namespace kinergy::expr
