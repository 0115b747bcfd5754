#include "api/errors.h"

#include <csignal>
#include <new>
#include <stdexcept>

#include "engine/gpu/gpu.h"
#include "engine/image/child_process.h"
#include "engine/image/image_io.h"
#include "scenes/input_error.h"

namespace facet::api {

void rethrowAsError() {
  try {
    throw;
  } catch (const v0::Error&) {
    throw;
  } catch (const scene::InputError& e) {
    throw v0::Error(v0::ErrorKind::BadInput, e.what());
  } catch (const std::invalid_argument& e) {
    throw v0::Error(v0::ErrorKind::BadInput, e.what());
  } catch (const OutputError& e) {
    throw v0::Error(v0::ErrorKind::OutputFailed, e.what());
  } catch (const gpu::Error& e) {
    throw v0::Error(v0::ErrorKind::GpuFailed, e.what());
  } catch (const Interrupted& e) {
    // The program facet ran has ended; the caller's process gets the signal
    // it would have had (Python: KeyboardInterrupt for SIGINT).
    raise(e.signal());
    throw v0::Error(v0::ErrorKind::Internal, e.what());
  } catch (const std::bad_alloc&) {
    throw v0::Error(v0::ErrorKind::Internal, "out of memory");
  } catch (const std::exception& e) {
    throw v0::Error(v0::ErrorKind::Internal, e.what());
  }
}

void refuse(const std::string& source, const std::string& field, const std::string& rule) {
  throw scene::InputError(source, 0, field, rule);
}

}  // namespace facet::api
