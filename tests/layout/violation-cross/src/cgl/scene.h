// The fixture system's own header.
#pragma once
