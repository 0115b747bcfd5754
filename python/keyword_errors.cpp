// Calls that pybind11 cannot match to a signature raise facet.Error naming
// the keyword facet does not take and the one meant, instead of pybind11's
// dump of every signature: each public function, method and constructor of
// the module is wrapped once, its docstring (and so its signature) kept.
#include <pybind11/eval.h>

#include "python/bindings.h"

namespace facet_python {
namespace {

// Python, run once over the finished module with `module` and `Error` bound.
constexpr const char* kWrapper = R"py(
import difflib, functools, re

def keywords(doc):
    """The parameter names of the first signature in a pybind11 docstring."""
    line = doc.splitlines()[0]
    return [n for n in re.findall(r"(?:\(|, )(\w+):", line[line.index("("):line.rindex(")")]) if n != "self"]

def diagnosed(function, owner):
    @functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as e:
            if not re.match(r"^[\w.]+\(\): incompatible (function|constructor) arguments", str(e)):
                raise
            names = keywords(function.__doc__)
            for given in kwargs:
                if given not in names:
                    near = difflib.get_close_matches(given, names, 1)
                    hint = f"; did you mean '{near[0]}'?" if near else ""
                    error = Error(f"{owner}: unknown keyword '{given}'{hint} (it takes: {', '.join(names)})")
                    error.exit_code = 1
                    raise error from None
            signature = function.__doc__.splitlines()[0]
            raise TypeError(f"{owner}: an argument is not of the type its parameter takes: {signature}") from None
    return call

for name in dir(module):
    value = getattr(module, name)
    if name.startswith("_") or value is Error:
        continue
    if isinstance(value, type):
        for member in ["__init__"] + [m for m in vars(value) if not m.startswith("_")]:
            method = vars(value).get(member)
            if callable(method) and getattr(method, "__doc__", None) and "(" in method.__doc__.splitlines()[0]:
                setattr(value, member, diagnosed(method, f"facet.{name}" + ("" if member == "__init__" else f".{member}")))
    elif callable(value):
        setattr(module, name, diagnosed(value, f"facet.{name}"))
)py";

}  // namespace

void nameUnknownKeywords(py::module_& m, const py::object& error) {
  py::dict scope;
  scope["module"] = m;
  scope["Error"] = error;
  py::exec(kWrapper, scope);
}

}  // namespace facet_python
