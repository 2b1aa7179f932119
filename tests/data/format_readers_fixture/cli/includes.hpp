#pragma once
#include<storage/read_file.hpp>
# include "storage/load_file.hpp"
#include <tinyxml2.h>
#include "storage/csv_lines.hpp"
#include "storage/atomic_file.hpp"
