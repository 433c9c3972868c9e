// The rows of a per-bond compute (LAMMPS `compute granbond/local`, LIGGGHTS
// `compute pair/gran/local/bond`) as both engines' `dump local` reads them:
// a vector of one value a row, or rows of several values through row
// pointers. The compute fills `values`, row after row, then publishes them.
#ifndef GRANBOND_LOCAL_ROWS_H
#define GRANBOND_LOCAL_ROWS_H

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace granbond {

class LocalRows {
public:
    LocalRows() = default;
    LocalRows(const LocalRows &) = delete;
    LocalRows &operator=(const LocalRows &) = delete;
    ~LocalRows()
    {
        std::free(data_);
        std::free(pointers_);
    }

    std::vector<double> values;

    // Hands `values` to the engine as rows of `cols` values (0: a vector of
    // one value a row): their number to `count`, and `vector` or `array`
    // pointed at them, as the compute's size_local_rows, vector_local and
    // array_local.
    void publish(int cols, int &count, double *&vector, double **&array)
    {
        const size_t width = static_cast<size_t>(std::max(cols, 1));
        count = static_cast<int>(values.size() / width);
        data_ = static_cast<double *>(std::realloc(data_, sizeof(double) * (values.size() + 1)));
        std::copy(values.begin(), values.end(), data_);
        if (cols == 0) {
            vector = data_;
            return;
        }
        pointers_ = static_cast<double **>(std::realloc(pointers_, sizeof(double *) * (count + 1)));
        for (int r = 0; r < count; r++) pointers_[r] = data_ + static_cast<size_t>(r) * width;
        array = pointers_;
    }

    // The bytes held, for the compute's memory_usage.
    double bytes() const { return static_cast<double>(values.capacity()) * 2 * sizeof(double); }

private:
    double *data_ = nullptr;
    double **pointers_ = nullptr;
};

}

#endif
