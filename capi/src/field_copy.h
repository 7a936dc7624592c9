// Copies between a C struct and the core struct with the same field names, through the generated field
// lists (generated_fields.h): NL_COPY_FIELDS(NL_LINK_SETTINGS_FIELDS, core, c) copies every plain number
// field the header declares, so a field added there is copied without an edit here.
#pragma once

#include "generated_fields.h"

#define NL_COPY_FIELDS(FIELDS, to, from)    \
    do {                                    \
        auto& nl_copy_to_ = (to);           \
        const auto& nl_copy_from_ = (from); \
        FIELDS(NL_COPY_ONE_FIELD_)          \
    } while (0)
#define NL_COPY_ONE_FIELD_(field) nl_copy_to_.field = nl_copy_from_.field;
