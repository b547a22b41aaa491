#include "backends.hpp"

namespace conformance {

std::vector<Backend>& backends() {
  static std::vector<Backend> list;
  return list;
}

}  // namespace conformance
