// The included side of the fixture.
#pragma once
