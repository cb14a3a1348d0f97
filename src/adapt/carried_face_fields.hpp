// SPDX-License-Identifier: BSD-3-Clause
// The host's face fields as an edit carries them: one FaceValues listener each
// (fields/face_values.hpp), attached for the lifetime of this object; the remapped values
// go back into the fields when it is done.
#pragma once

#include "adapt/surface_data.hpp"
#include "fields/face_values.hpp"

#include <vector>

namespace sfa {

class CarriedFaceFields {
public:
    CarriedFaceFields(MeshEdit &edit, std::vector<FaceField> &fields) : edit_(edit), fields_(fields)
    {
        listeners_.reserve(fields.size()); // attached by address: no reallocation after
        for (FaceField &field : fields) {
            listeners_.emplace_back(field.ncomp, std::move(field.values));
            edit_.attach(listeners_.back());
        }
    }
    ~CarriedFaceFields()
    {
        for (size_t f = 0; f < listeners_.size(); ++f) {
            edit_.detach(listeners_[f]);
            fields_[f].values = listeners_[f].take_values();
        }
    }
    CarriedFaceFields(const CarriedFaceFields &) = delete;
    CarriedFaceFields &operator=(const CarriedFaceFields &) = delete;

private:
    MeshEdit &edit_;
    std::vector<FaceField> &fields_;
    std::vector<FaceValues> listeners_;
};

} // namespace sfa
