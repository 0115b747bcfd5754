#include "api/errors.h"

#include <new>
#include <stdexcept>

#include "engine/gpu/gpu.h"
#include "engine/image/image_io.h"
#include "scenes/input_error.h"

namespace facet::v0::detail {

void rethrowAsError() {
  try {
    throw;
  } catch (const Error&) {
    throw;
  } catch (const scene::InputError& e) {
    throw Error(ErrorKind::BadInput, e.what());
  } catch (const std::invalid_argument& e) {
    throw Error(ErrorKind::BadInput, e.what());
  } catch (const OutputError& e) {
    throw Error(ErrorKind::OutputFailed, e.what());
  } catch (const gpu::Error& e) {
    throw Error(ErrorKind::GpuFailed, e.what());
  } catch (const std::bad_alloc&) {
    throw Error(ErrorKind::Internal, "out of memory");
  } catch (const std::exception& e) {
    throw Error(ErrorKind::Internal, e.what());
  }
}

}  // namespace facet::v0::detail
