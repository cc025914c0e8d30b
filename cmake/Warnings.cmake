# SAFESTATE_WARNINGS: the compiler warnings of the code that runs in a controller or drives
# it from Python -- the library, its components (cmake/ComponentLibrary.cmake), the Python
# bindings (bindings/python/, cmake/BindingModule.cmake) -- and they are errors.
# Third-party headers (Eigen, pybind11, Python) are system includes: not warned about.
set(SAFESTATE_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror)
