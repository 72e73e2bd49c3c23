// A model reader module (io/model_reader.hpp) from another build, for
// model_reader_test.cpp: its entry point says another version.
#include "io/model_reader.hpp"

extern "C" JT_MODEL_READER_EXPORT const jt::ModelReader* jt_model_reader() {
    static const jt::ModelReader reader{"0.0.0 (another build)", nullptr};
    return &reader;
}
