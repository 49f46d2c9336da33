@compute @workgroup_size(1)
fn f() {
    var i : i32;
    var result : i32;
    switch(i) {
        default: {
            result = 44;
            break;
        }
    }
}
