// A model reader module (io/model_reader.hpp) from another build, for
// model_reader_test.cpp: of the version JT_FAKE_VERSION names, else of this
// version with types of other sizes.
#include "io/model_reader.hpp"
#include "jtracer/version.hpp"

#include <cstdlib>

extern "C" JT_MODEL_READER_EXPORT const jt::ModelReader* jt_model_reader() {
    const char* version = std::getenv("JT_FAKE_VERSION");
    static const jt::ModelReader reader{version ? version : jt::project_version.data(),
                                        jt::model_reader_layout() + 1, nullptr};
    return &reader;
}
